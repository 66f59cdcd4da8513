// setting_checks.cpp - ranges of the shared settings.
#include "setting_checks.h"

#include <cmath>
#include <string>

#include "rt_grid.h"
#include "rt_scene.h"
#include "user_error.h"

namespace torusrt {

void check_cells(const std::array<int, 3> &cells)
{
    unsigned long long product = 1;
    for (int n : cells) {
        if (n < 1 || n > RT_GRID_MAX_CELLS_PER_AXIS)
            throw UserError(
                "--cells: each axis must have 1 to " + std::to_string(RT_GRID_MAX_CELLS_PER_AXIS) + " cells", 2);
        product *= static_cast<unsigned long long>(n);
    }
    if (product > RT_GRID_MAX_CELLS)
        throw UserError("--cells: at most " + std::to_string(RT_GRID_MAX_CELLS) + " cells in all", 2);
}

void check_image_size(const char *option, unsigned width, unsigned height)
{
    if (width == 0 && height == 0) return;
    if (width < 1 || height < 1 || width > RT_SCENE_MAX_RESOLUTION || height > RT_SCENE_MAX_RESOLUTION)
        throw UserError(std::string(option) + " " + std::to_string(width) + "x" + std::to_string(height) +
                            ": each side must be 1 to " + std::to_string(RT_SCENE_MAX_RESOLUTION),
                        2);
}

void check_step_limits(const rt_step_params &step)
{
    if (step.max_depth < 0 || step.max_depth > 1000)
        throw UserError("--max-depth " + std::to_string(step.max_depth) + ": must be 0 to 1000", 2);
    if (!(step.min_weight >= 0) || !std::isfinite(step.min_weight))
        throw UserError("--min-weight: must be a non-negative number", 2);
}

}  // namespace torusrt
