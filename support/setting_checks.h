// setting_checks.h - range checks of the settings both executables have (cells, image size,
// shade-tree limits), shared by the model's validator and the reference renderer.
#pragma once

#include <array>

#include "rt_step.h"

namespace torusrt {

// Each throws UserError (exit 2) naming the option.
void check_cells(const std::array<int, 3> &cells);                           // --cells
void check_image_size(const char *option, unsigned width, unsigned height);  // 0x0 = the scene's
void check_step_limits(const rt_step_params &step);                          // --max-depth, --min-weight

}  // namespace torusrt
