// cost_mapping.cpp - the pilot and the Scotch mapping behind --map cost.
#include "cost_mapping.h"

#include "user_error.h"

namespace torusrt {

nlohmann::json cost_mapping(const SimConfig &, const rt_scene *, const rt_grid *, std::vector<int32_t> &)
{
    throw UserError("--map cost: not available in this build", 2);
}

}  // namespace torusrt
