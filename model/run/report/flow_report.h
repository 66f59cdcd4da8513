// flow_report.h - the `flow` section of a run's report: the flow-control scheme, the capacity of
// every buffer in packets, the packet memory that makes per processor, and per queue and per
// class the most packets held at once (docs/model.md, flow control).
#pragma once

#include <nlohmann/json.hpp>

#include "rt_scene.h"
#include "sim_config.h"

namespace torusrt {

class TorusSystem;

nlohmann::json flow_report_json(const SimConfig &config, TorusSystem &top, const rt_scene *scene);

}  // namespace torusrt
