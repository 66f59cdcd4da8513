// option_docs.cpp - markdown tables written from the option tables.
#include "option_docs.h"

#include <cmath>

#include "combination_rules.h"
#include "machine_options.h"
#include "option_parsing.h"
#include "run_options.h"

namespace torusrt {

namespace {

// `text` in a table cell: a '|' escaped.
std::string cell(const std::string &text)
{
    std::string s;
    for (char c : text) s += c == '|' ? std::string("\\|") : std::string(1, c);
    return s;
}

std::string code(const std::string &text) { return text.empty() ? "" : "`" + cell(text) + "`"; }

std::string bound(double v) { return std::isinf(v) ? std::string("any") : number_text(v); }

// "0 to 100000000" for a number or time, "" for other kinds.
std::string range(const OptionSpec &s)
{
    if (s.kind != ValueKind::integer && s.kind != ValueKind::real && s.kind != ValueKind::time) return "";
    return bound(s.min) + " to " + bound(s.max);
}

std::string block(const std::string &name, const std::string &body)
{
    return "<!-- BEGIN generated: " + name + " (torusrt-sim --option-tables) -->\n" + body +
           "<!-- END generated: " + name + " -->\n";
}

std::string file_tables()
{
    const MachineConfig defaults = machine_from_texts({});
    const nlohmann::json tables = machine_option_tables_json(defaults);
    std::string s = "| table | keys |\n| --- | --- |\n";
    for (const std::string &table : machine_file_tables()) {
        std::string keys;
        for (const MachineOption &o : machine_option_table())
            if (o.table == table) keys += (keys.empty() ? "`" : ", `") + o.spec.key + "`";
        s += "| `[" + table + "]` | " + keys + " |\n";
    }
    return s;
}

std::string machine_reference()
{
    const MachineConfig defaults = machine_from_texts({});
    std::string s = "| option | value | default | range | unit | JSON `config` keys | T(1) run | meaning |\n"
                    "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const MachineOption &o : machine_option_table()) {
        const OptionSpec &spec = o.spec;
        std::string json;
        if (o.json) {
            nlohmann::json j = nlohmann::json::object();
            o.json(defaults, j);
            for (const auto &kv : j.items()) json += (json.empty() ? "" : ", ") + code(kv.key());
        }
        s += "| " + code(spec.long_name()) + " | " + code(spec.value_name) + " | " + code(spec.default_text) + " | " +
             range(spec) + " | " + spec.unit + " | " + json + " | " +
             (o.one_processor ? code(o.one_processor) : std::string("kept")) + " | " + cell(spec.help) + " |\n";
    }
    return s;
}

std::string run_reference()
{
    std::string s = "| option | value | default | range | unit | group | meaning |\n"
                    "| --- | --- | --- | --- | --- | --- | --- |\n";
    for (const RunOption &o : run_option_table()) {
        const OptionSpec &spec = o.spec;
        s += "| " + code(spec.long_name()) + " | " + code(spec.value_name) + " | " + code(spec.default_text) + " | " +
             range(spec) + " | " + spec.unit + " | " + group_title(spec.group) + " | " + cell(spec.help) + " |\n";
    }
    return s;
}

std::string rule_reference()
{
    std::string s = "| option | rule | of |\n| --- | --- | --- |\n";
    for (const CombinationRule &r : combination_rules())
        s += "| " + code(r.option) + " | " + cell(r.rule) + " | " + (r.of_machine ? "machine" : "run") + " |\n";
    return s;
}

}  // namespace

std::string option_tables_markdown()
{
    return block("machine file tables", file_tables()) + block("machine options", machine_reference()) +
           block("run options", run_reference()) + block("combination rules", rule_reference());
}

}  // namespace torusrt
