// option_registration.cpp - specs turned into CLI11 options, and the help laid out to fit.
#include "option_registration.h"

#include <sstream>

namespace torusrt {

namespace {

constexpr size_t kNameColumn = 30;  // CLI11's column for the descriptions

class HelpLayout : public CLI::Formatter {
  public:
    HelpLayout(std::string usage, std::string rules, std::string examples)
        : m_usage(std::move(usage)), m_rules(std::move(rules)), m_examples(std::move(examples))
    {
        column_width(kNameColumn);
    }
    std::string make_usage(const CLI::App *, std::string) const override { return m_usage + "\n\n" + m_rules + "\n"; }
    std::string make_footer(const CLI::App *app) const override
    {
        return "\nExamples:\n" + m_examples + "\n" + CLI::Formatter::make_footer(app);
    }

  private:
    std::string m_usage, m_rules, m_examples;
};

}  // namespace

std::string wrapped(const std::string &text, size_t width)
{
    std::istringstream words(text);
    std::string out, line, word;
    while (words >> word) {
        if (!line.empty() && line.size() + 1 + word.size() > width) {
            out += line + "\n";
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    return out + line;
}

CLI::Option *add_spec_option(CLI::App &app, const OptionSpec &spec)
{
    std::string help = wrapped(spec.full_help(), kHelpColumns - kNameColumn - 1);
    CLI::Option *opt = spec.kind == ValueKind::flag ? app.add_flag(spec.name) : app.add_option(spec.name);
    if (spec.kind == ValueKind::flag) opt->multi_option_policy(CLI::MultiOptionPolicy::Throw);  // once, as every option
    opt->description(help);
    if (!spec.value_name.empty()) opt->type_name(spec.value_name);
    opt->group(group_title(spec.group));
    opt->configurable(!spec.key.empty());
    return opt;
}

void retitle_group(CLI::App &app, const std::string &from, const std::string &to)
{
    for (CLI::Option *opt : app.get_options())
        if (opt->get_group() == from) opt->group(to);
}

std::map<std::string, std::string> given_options(const CLI::App &app)
{
    std::map<std::string, std::string> given;
    for (const CLI::Option *opt : app.get_options()) {
        if (opt->count() == 0 || opt == app.get_help_ptr() || opt == app.get_config_ptr()) continue;
        std::string name = opt->get_positional() ? opt->get_name() : "--" + opt->get_single_name();
        if (!opt->get_lnames().empty()) name = "--" + opt->get_lnames().front();
        given[name] = opt->get_type_size_max() == 0 ? "true" : opt->results().back();
    }
    return given;
}

void set_help_layout(CLI::App &app, const std::string &usage, const std::string &rules, const std::string &examples)
{
    app.formatter(std::make_shared<HelpLayout>(usage, rules, examples));
}

std::string option_suggestion(const CLI::App &app, const std::string &typed)
{
    std::vector<std::string> names;
    for (const CLI::Option *opt : app.get_options())
        for (const std::string &n : opt->get_lnames()) names.push_back("--" + n);
    std::string best = closest_name(typed, names);
    return best.empty() ? "" : "did you mean " + best + "?";
}

}  // namespace torusrt
