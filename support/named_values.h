// named_values.h - one table of names per enumerated setting: the names the options accept are
// the names the reports print.
#pragma once

#include <cstddef>
#include <string>

#include "user_error.h"

namespace torusrt {

template <typename E> struct NamedValue {
    E value;
    const char *name;
};

// The name of `value` in `table` ("unknown" if it has none).
template <typename E, size_t N> const char *name_in(const NamedValue<E> (&table)[N], E value)
{
    for (const auto &entry : table)
        if (entry.value == value) return entry.name;
    return "unknown";
}

// "a, b or c": the names of `table` for a message.
template <typename E, size_t N> std::string names_of(const NamedValue<E> (&table)[N])
{
    std::string s;
    for (size_t i = 0; i < N; i++) s += std::string(i == 0 ? "" : i + 1 == N ? " or " : ", ") + table[i].name;
    return s;
}

// The value named `text`; UserError (exit 2) naming `option` and the names it accepts.
template <typename E, size_t N>
E value_named(const std::string &option, const std::string &text, const NamedValue<E> (&table)[N])
{
    for (const auto &entry : table)
        if (text == entry.name) return entry.value;
    throw UserError(option + " '" + text + "': expected " + names_of(table), 2);
}

}  // namespace torusrt
