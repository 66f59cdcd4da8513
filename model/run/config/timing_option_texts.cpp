// timing_option_texts.cpp - the timing table read from and written as the options' text.
#include "timing_option_texts.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "option_parsing.h"
#include "timing_choice.h"
#include "timing_limits.h"
#include "user_error.h"

namespace torusrt {

double timing_value(const rt_timing &t, const char *key)
{
    for (size_t i = 0; i < rt_timing_key_count(); i++)
        if (std::strcmp(rt_timing_key_name(i), key) == 0) return rt_timing_get(&t, i);
    return 0;
}

nlohmann::json timing_json(const rt_timing &t)
{
    nlohmann::json j;
    for (size_t i = 0; i < rt_timing_key_count(); i++) j[rt_timing_key_name(i)] = rt_timing_get(&t, i);
    return j;
}

void set_timing(const OptionSpec &spec, rt_timing &t, const char *key, double v)
{
    char msg[RT_MSG_LEN] = "";
    if (rt_timing_set(&t, key, v, msg, sizeof msg) != RT_OK) throw UserError(spec.long_name() + ": " + msg, 2);
}

// --timing FILE: the table of the profile with the file's values on top.
void read_timing_file(const OptionSpec &, const std::string &t, MachineConfig &m)
{
    if (t.empty()) return;
    m.timing_profile = choose_timing(m.timing_base, t, &m.timing);
    m.timing_file = t;
    // The table as loaded is input: a value out of range is the file's fault, named at its line.
    std::string key, problem = timing_limit_problem(m.timing, &key);
    long line = problem.empty() ? 0 : timing_key_line(t, key);
    if (!problem.empty())
        throw UserError("--timing: " + shown_text(t) + (line > 0 ? ":" + std::to_string(line) : "") + ": " + problem);
}

// "KEY=VALUE,..." of every timing key, each key once; no empty item (a stray comma).
void read_timing_values(const OptionSpec &spec, const std::string &text, MachineConfig &m)
{
    std::vector<std::string> seen;
    size_t pos = 0;
    while (pos < text.size()) {
        size_t comma = text.find(',', pos);
        std::string item = text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
        if (item.empty() || (comma + 1 == text.size()))
            throw UserError(spec.long_name() + " '" + shown_text(text) +
                                "': an empty item (a comma with no KEY=VALUE " + (item.empty() ? "before" : "after") +
                                " it)",
                            2);
        size_t eq = item.find('=');
        if (eq == std::string::npos)
            throw UserError(spec.long_name() + " '" + shown_text(item) + "': expected KEY=VALUE", 2);
        std::string key = item.substr(0, eq);
        if (std::find(seen.begin(), seen.end(), key) != seen.end())
            throw UserError(
                spec.long_name() + " '" + shown_text(item) + "': the key '" + shown_text(key) + "' is given twice", 2);
        seen.push_back(key);
        set_timing(spec, m.timing, key.c_str(),
                   parse_real(spec.long_name() + " " + key, item.substr(eq + 1), 0, kMaxTimingUs));
        if (comma == std::string::npos) break;
        pos = comma + 1;
    }
    m.timing_file.clear();
    m.timing_values = true;
    m.timing_profile = m.timing_base + " + values";
}

std::string timing_values_text(const MachineConfig &m)
{
    std::string s;
    for (size_t i = 0; i < rt_timing_key_count(); i++)
        s += std::string(i ? "," : "") + rt_timing_key_name(i) + "=" + number_text(rt_timing_get(&m.timing, i));
    return s;
}

}  // namespace torusrt
