// mapping_registry.cpp - the mappings by name, in the help's order: a new mapping is its own
// file defining its Mapping and one line here.
#include "mapping.h"
#include "name_registry.h"
#include "user_error.h"

namespace torusrt {

extern const Mapping kBlockMapping, kCyclicMapping, kBlockCyclicMapping, kCostMapping, kScatterMapping, kFileMapping;

namespace {

const NameRegistry<const Mapping *> &registry()
{
    static const NameRegistry<const Mapping *> table = {
        {kBlockMapping.name, &kBlockMapping},
        {kCyclicMapping.name, &kCyclicMapping},
        {kBlockCyclicMapping.name, &kBlockCyclicMapping},
        {kCostMapping.name, &kCostMapping},
        {kScatterMapping.name, &kScatterMapping},
        {kFileMapping.name, &kFileMapping},
    };
    return table;
}

}  // namespace

int unfolded(const MachineConfig &) { return 1; }

const Mapping *find_mapping(const std::string &name)
{
    const Mapping *const *m = registry().find(name);
    return m ? *m : nullptr;
}

const Mapping &mapping_of(const MachineConfig &config)
{
    const Mapping *m = find_mapping(config.mapping);
    if (!m) throw UserError("--map '" + config.mapping + "': expected " + mapping_forms(), 2);
    return *m;
}

const char *file_mapping_name()
{
    for (const std::string &name : mapping_names())
        if (find_mapping(name)->from_file) return find_mapping(name)->name;
    return "";
}

std::vector<std::string> mapping_names() { return registry().names(); }

std::string mapping_forms()
{
    std::vector<std::string> forms;
    for (const std::string &name : mapping_names())
        if (*find_mapping(name)->forms) forms.push_back(find_mapping(name)->forms);
    std::string s;
    for (size_t i = 0; i < forms.size(); i++)
        s += std::string(i == 0 ? "" : i + 1 == forms.size() ? " or " : ", ") + forms[i];
    return s;
}

std::string mapping_text(const MachineConfig &config)
{
    const Mapping &m = mapping_of(config);
    bool shown =
        m.parameter == MappingParameter::required || (m.parameter == MappingParameter::optional && config.block > 1);
    return shown ? std::string(m.name) + ":" + std::to_string(config.block) : std::string(m.name);
}

}  // namespace torusrt
