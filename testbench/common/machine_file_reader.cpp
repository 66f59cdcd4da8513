// machine_file_reader.cpp - the lines of a machine file parsed here rather than by CLI11, whose
// reader cuts a value at its first '#' even inside quotes and knows no escapes.
#include "machine_file_reader.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <sstream>

#include "option_parsing.h"
#include "option_spec.h"

namespace torusrt {

namespace {

std::string trimmed(const std::string &s)
{
    size_t b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

void append_utf8(std::string &out, unsigned long cp)
{
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xc0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3f));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xe0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
        out += static_cast<char>(0x80 | (cp & 0x3f));
    } else {
        out += static_cast<char>(0xf0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3f));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
        out += static_cast<char>(0x80 | (cp & 0x3f));
    }
}

// A quoted string starting at s[i] (the quote); sets `i` past the closing quote. "" and false on
// a bad escape or no closing quote, with `why` set.
bool quoted_string(const std::string &s, size_t &i, std::string &out, std::string &why)
{
    char quote = s[i++];
    for (; i < s.size(); i++) {
        char c = s[i];
        if (c == quote) {
            i++;
            return true;
        }
        if (c != '\\' || quote == '\'') {
            out += c;
            continue;
        }
        if (++i == s.size()) break;
        switch (s[i]) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case 'b': out += '\b'; break;
        case 't': out += '\t'; break;
        case 'n': out += '\n'; break;
        case 'f': out += '\f'; break;
        case 'r': out += '\r'; break;
        case 'u':
        case 'U': {
            size_t n = s[i] == 'u' ? 4 : 8;
            std::string hex = s.substr(i + 1, n);
            if (hex.size() != n || hex.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos) {
                why = "a \\u escape needs " + std::to_string(n) + " hexadecimal digits";
                return false;
            }
            unsigned long cp = std::stoul(hex, nullptr, 16);
            if (cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) {
                why = "a \\u escape outside Unicode";
                return false;
            }
            append_utf8(out, cp);
            i += n;
            break;
        }
        default: why = "an unknown escape \\" + shown_text(std::string(1, s[i])); return false;
        }
    }
    why = std::string("no closing ") + quote;
    return false;
}

}  // namespace

MachineFileReader::MachineFileReader(std::vector<std::string> keys, std::vector<std::string> timed_keys)
    : m_keys(std::move(keys)), m_timed_keys(std::move(timed_keys))
{
}

int MachineFileReader::line_of(const std::string &key) const
{
    auto it = m_lines.find(key);
    return it == m_lines.end() ? 0 : it->second;
}

std::vector<CLI::ConfigItem> MachineFileReader::from_config(std::istream &input) const
{
    std::vector<CLI::ConfigItem> items;
    m_lines.clear();
    std::string raw;
    for (int n = 1; std::getline(input, raw); n++) {
        if (n == 1 && raw.compare(0, 3, "\xef\xbb\xbf") == 0) raw.erase(0, 3);  // a UTF-8 byte-order mark
        if (raw.find('\0') != std::string::npos) throw MachineFileError(n, "a NUL byte: not a machine file");
        std::string line = trimmed(raw);
        if (line.empty() || line[0] == '#') continue;
        if (line[0] == '[') throw MachineFileError(n, shown_text(line) + ": a machine file has no sections");
        size_t eq = line.find('=');
        if (eq == std::string::npos) throw MachineFileError(n, "expected key = \"value\"");
        std::string key = trimmed(line.substr(0, eq)), why;
        if (!key.empty() && (key[0] == '"' || key[0] == '\'')) {
            size_t i = 0;
            std::string name;
            if (!quoted_string(key, i, name, why) || i != key.size()) throw MachineFileError(n, "a bad key: " + why);
            key = name;
        }
        if (key.empty()) throw MachineFileError(n, "no key before '='");
        std::string rest = trimmed(line.substr(eq + 1)), value;
        size_t end = 0;
        if (!rest.empty() && (rest[0] == '"' || rest[0] == '\'')) {
            if (!quoted_string(rest, end, value, why)) throw MachineFileError(n, shown_text(key) + ": " + why);
        } else {  // a bare word: up to a comment
            end = rest.find('#');
            value = trimmed(rest.substr(0, end));
            end = end == std::string::npos ? rest.size() : end;
        }
        std::string after = trimmed(rest.substr(end));
        if (!after.empty() && after[0] != '#')
            throw MachineFileError(n, shown_text(key) + ": text after the value: " + shown_text(after));
        if (std::find(m_keys.begin(), m_keys.end(), key) == m_keys.end()) {
            std::string near = closest_name(key, m_keys);
            throw MachineFileError(n, shown_text(key) + ": not a machine option" +
                                          (near.empty() ? "" : " (did you mean " + near + "?)"));
        }
        if (!m_lines.emplace(key, n).second) throw MachineFileError(n, key + ": given twice");
        bool timed = std::find(m_timed_keys.begin(), m_timed_keys.end(), key) != m_timed_keys.end();
        if (timed && !value.empty() && value != "0" && !has_time_unit(value))
            throw MachineFileError(n, key + " = \"" + shown_text(value) +
                                          "\": a time in a machine file needs its unit (us, ms or s), "
                                          "e.g. \"500us\"");
        CLI::ConfigItem item;
        item.name = key;
        item.inputs = {value};
        items.push_back(std::move(item));
    }
    return items;
}

}  // namespace torusrt
