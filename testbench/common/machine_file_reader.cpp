// machine_file_reader.cpp - the lines of a machine file checked and cleaned, then handed to
// CLI11's reader. CLI11 cuts a value at its first '#', even inside quotes, so a path such as
// "run #2.timing" would be read as "run; here comments are removed first, quotes respected.
#include "machine_file_reader.h"

#include <set>
#include <sstream>
#include <string>

namespace torusrt {

namespace {

// The line without a comment: '#' outside '...' or "..." and everything after it.
std::string without_comment(const std::string &line)
{
    char quote = 0;
    for (size_t i = 0; i < line.size(); i++) {
        char c = line[i];
        if (quote != 0) {
            if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (c == '#') {
            return line.substr(0, i);
        }
    }
    return line;
}

std::string trimmed(const std::string &s)
{
    size_t b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::string unquoted(const std::string &s)
{
    if (s.size() >= 2 && (s.front() == '"' || s.front() == '\'') && s.back() == s.front())
        return s.substr(1, s.size() - 2);
    return s;
}

CLI::ConfigError line_error(int line, const std::string &what)
{
    return CLI::ConfigError("line " + std::to_string(line) + ": " + what);
}

}  // namespace

MachineFileReader::MachineFileReader()
{
    commentChar = '\0';  // comments are gone before CLI11 reads the text
}

std::vector<CLI::ConfigItem> MachineFileReader::from_config(std::istream &input) const
{
    std::string cleaned, raw;
    std::set<std::string> keys;
    for (int n = 1; std::getline(input, raw); n++) {
        if (n == 1 && raw.compare(0, 3, "\xEF\xBB\xBF") == 0) raw.erase(0, 3);  // a byte-order mark
        std::string line = trimmed(without_comment(raw));
        cleaned += line + "\n";
        if (line.empty()) continue;
        if (line.front() == '[') throw line_error(n, line + ": a machine file has no sections");
        std::string key = unquoted(trimmed(line.substr(0, line.find('='))));
        if (!keys.insert(key).second) throw line_error(n, key + ": given twice");
    }
    std::istringstream text(cleaned);
    return CLI::ConfigBase::from_config(text);
}

}  // namespace torusrt
