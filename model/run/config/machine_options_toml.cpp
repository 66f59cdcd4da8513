// machine_options_toml.cpp - the machine file written from the option table: a [table] per part,
// each value a TOML basic string.
#include <cstdio>

#include "machine_options.h"
#include "option_parsing.h"
#include "user_error.h"

namespace torusrt {

namespace {

// A TOML basic string: quotes, backslashes and control bytes escaped; bytes that are not
// UTF-8 cannot be written at all (TOML files are UTF-8).
std::string toml_string(const std::string &key, const std::string &v)
{
    std::string out = "\"";
    for (size_t i = 0; i < v.size(); i++) {
        unsigned char c = static_cast<unsigned char>(v[i]);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c < 0x20 || c == 0x7f) {
            char esc[8];
            std::snprintf(esc, sizeof esc, "\\u%04X", c);
            out += esc;
        } else if (c >= 0x80) {  // one UTF-8 sequence, checked
            size_t n = c >= 0xf0 && c < 0xf5 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 && c < 0xe0 ? 2 : 0;
            bool ok = n > 0 && i + n <= v.size();
            for (size_t k = 1; ok && k < n; k++) ok = (static_cast<unsigned char>(v[i + k]) & 0xc0) == 0x80;
            if (!ok)
                throw UserError("--" + key + " '" + shown_text(v) +
                                    "': a value that is not UTF-8 cannot be written to a machine file",
                                2);
            out.append(v, i, n);
            i += n - 1;
        } else {
            out += static_cast<char>(c);
        }
    }
    return out + "\"";
}

}  // namespace

std::string machine_options_toml(const MachineConfig &m, bool with_timing)
{
    const nlohmann::json tables = machine_option_tables_json(m);
    std::string s, table;
    for (const auto &kv : machine_options(m, with_timing)) {
        const std::string &in = tables.at(kv.first).get_ref<const std::string &>();
        if (in != table) s += (table.empty() ? "[" : "\n[") + in + "]\n";
        table = in;
        s += kv.first + "=" + toml_string(kv.first, kv.second) + "\n";
    }
    return s;
}

}  // namespace torusrt
