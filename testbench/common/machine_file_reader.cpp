// machine_file_reader.cpp - a machine file parsed by toml++ (its syntax, escapes and UTF-8
// checks), then checked key by key against the machine's option table; CLI11 gets the values as
// the command line would give them.
#include "machine_file_reader.h"

#include <algorithm>
#include <iterator>
#include <sstream>
#include <toml++/toml.h>

#include "option_parsing.h"
#include "option_spec.h"

namespace torusrt {

namespace {

// A key or value of the file with where it stands; `table` is "" for a key at the top.
struct Entry {
    std::string key, table;
    const toml::node *value;
    toml::source_position where;
};

bool before(const toml::source_position &a, const toml::source_position &b)
{
    return a.line != b.line ? a.line < b.line : a.column < b.column;
}

std::string position_text(const toml::source_position &p)
{
    return std::to_string(p.line) + ":" + std::to_string(p.column);
}

// The source text of the number that starts at `p` (toml++ counts columns in code points): the
// number as written, for the project's number parser to judge.
std::string number_source(const std::vector<std::string> &lines, const toml::source_position &p)
{
    if (p.line == 0 || p.line > lines.size()) return "";
    const std::string &line = lines[p.line - 1];
    size_t i = 0;
    for (toml::source_index column = 1; i < line.size(); i++) {
        if ((static_cast<unsigned char>(line[i]) & 0xc0) == 0x80) continue;  // inside a code point
        if (column++ == p.column) break;
    }
    size_t end = line.find_first_of(" \t\r#,]}", i);
    return line.substr(i, end == std::string::npos ? std::string::npos : end - i);
}

// "a, b or c".
std::string listed(const std::vector<std::string> &names)
{
    std::string s;
    for (size_t i = 0; i < names.size(); i++) s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return s;
}

// The keys and values of a parsed file, flat or in one of `tables`, in the file's order; a table
// that is none of them, an array of tables, an inline table for a table and a table in a table
// are errors.
std::vector<Entry> entries_of(const toml::table &root, const std::vector<std::string> &tables)
{
    std::vector<Entry> entries;
    for (auto &&[key, node] : root) {
        const std::string name(key.str());
        const toml::source_position at = key.source().begin;
        if (node.is_array_of_tables())
            throw MachineFileError(at.line, at.column,
                                   "[[" + shown_text(name) + "]]: an array of tables; a machine file's tables are [" +
                                       shown_text(name) + "]");
        const toml::table *table = node.as_table();
        if (table == nullptr) {
            entries.push_back({name, "", &node, at});
            continue;
        }
        if (std::find(tables.begin(), tables.end(), name) == tables.end()) {
            std::string near = closest_name(name, tables);
            throw MachineFileError(at.line, at.column,
                                   "[" + shown_text(name) + "]: not a table of a machine file (" + listed(tables) +
                                       (near.empty() ? "" : "; did you mean [" + near + "]?") + ")");
        }
        if (table->is_inline())
            throw MachineFileError(at.line, at.column,
                                   shown_text(name) + ": an inline table; write [" + name + "] and its keys below it");
        for (auto &&[inner_key, inner] : *table) {
            const toml::source_position where = inner_key.source().begin;
            if (inner.is_table() && !inner.as_table()->is_inline())
                throw MachineFileError(where.line, where.column,
                                       "[" + name + "." + shown_text(std::string(inner_key.str())) +
                                           "]: a machine file's tables hold no tables");
            entries.push_back({std::string(inner_key.str()), name, &inner, where});
        }
    }
    std::sort(entries.begin(), entries.end(), [](const Entry &a, const Entry &b) { return before(a.where, b.where); });
    return entries;
}

// The text an entry's value gives its option: a string as it is, a boolean as true or false, a
// number as its source text (judged by the option's parser); anything else is an error.
std::string value_text(const Entry &e, const std::vector<std::string> &lines)
{
    const toml::node &v = *e.value;
    const long line = e.where.line, column = e.where.column;
    if (v.is_string()) return v.as_string()->get();
    if (v.is_boolean()) return v.as_boolean()->get() ? "true" : "false";
    if (v.is_number()) return number_source(lines, v.source().begin);
    if (v.is_array())
        throw MachineFileError(line, column,
                               e.key + ": an array; a machine option takes one value (a list is one string, e.g. "
                                       "\"a,b\")");
    if (v.is_table())
        throw MachineFileError(line, column, e.key + ": an inline table; a machine option takes one value");
    throw MachineFileError(line, column, e.key + ": a date or time; a machine option takes a string");
}

}  // namespace

MachineFileReader::MachineFileReader(std::vector<std::pair<std::string, std::string>> keys,
                                     std::vector<std::string> timed_keys)
    : m_keys(std::move(keys)), m_timed_keys(std::move(timed_keys))
{
}

std::string MachineFileReader::position_of(const std::string &key) const
{
    auto it = m_positions.find(key);
    return it == m_positions.end() ? "" : it->second;
}

std::vector<CLI::ConfigItem> MachineFileReader::from_config(std::istream &input) const
{
    m_positions.clear();
    std::string text{std::istreambuf_iterator<char>(input), std::istreambuf_iterator<char>()};
    toml::table root;
    try {
        root = toml::parse(text);
    } catch (const toml::parse_error &e) {
        throw MachineFileError(e.source().begin.line, e.source().begin.column, std::string(e.description()));
    }
    std::vector<std::string> key_names, tables;
    for (const auto &kt : m_keys) {
        key_names.push_back(kt.first);
        if (std::find(tables.begin(), tables.end(), kt.second) == tables.end()) tables.push_back(kt.second);
    }
    std::vector<std::string> lines;
    std::istringstream split(text);
    for (std::string line; std::getline(split, line);) lines.push_back(line);
    std::vector<CLI::ConfigItem> items;
    for (const Entry &e : entries_of(root, tables)) {
        const long line = e.where.line, column = e.where.column;
        auto known = std::find_if(m_keys.begin(), m_keys.end(), [&](const auto &kt) { return kt.first == e.key; });
        if (known == m_keys.end()) {
            std::string near = closest_name(e.key, key_names);
            throw MachineFileError(line, column,
                                   shown_text(e.key) + ": not a machine option" +
                                       (near.empty() ? "" : " (did you mean " + near + "?)"));
        }
        if (!e.table.empty() && e.table != known->second)
            throw MachineFileError(line, column,
                                   e.key + ": a key of [" + known->second + "], not of [" + e.table + "]");
        if (m_positions.count(e.key))
            throw MachineFileError(line, column, e.key + ": given twice (also at " + m_positions[e.key] + ")");
        std::string value = value_text(e, lines);
        bool timed = std::find(m_timed_keys.begin(), m_timed_keys.end(), e.key) != m_timed_keys.end();
        if (timed && !value.empty() && value != "0" && !has_time_unit(value))
            throw MachineFileError(line, column,
                                   e.key + " = \"" + shown_text(value) +
                                       "\": a time in a machine file needs its unit (us, ms or s), e.g. \"500us\"");
        m_positions[e.key] = position_text(e.value->source().begin);
        CLI::ConfigItem item;
        item.name = e.key;
        item.inputs = {value};
        items.push_back(std::move(item));
    }
    return items;
}

}  // namespace torusrt
