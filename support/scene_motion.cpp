// scene_motion.cpp - reading a motion file, and moving the scene and its cell lists per frame.
#include "scene_motion.h"

#include <cstdio>

#include "scene_setup.h"
#include "user_error.h"

namespace torusrt {

MotionPtr read_motion_file(const std::string &path)
{
    if (path.empty()) return nullptr;
    char msg[RT_MSG_LEN] = "";
    rt_motion *raw = nullptr;
    // A motion file, like a --camera-path, is part of the command line: a bad one is exit 2.
    if (rt_motion_load(path.c_str(), &raw, msg, sizeof msg) != RT_OK)
        throw UserError(std::string("--motion: ") + msg, 2);
    return MotionPtr(raw);
}

SceneMotion::SceneMotion(MotionPtr motion, ScenePtr scene, const std::string &path, bool quiet)
    : m_motion(std::move(motion)), m_scene(std::move(scene)), m_path(path)
{
    char msg[RT_MSG_LEN] = "";
    rt_status st = rt_motion_space(m_motion.get(), m_scene.get(), &m_space, msg, sizeof msg);
    if (st == RT_ERR_NOMEM) throw UserError(std::string("--motion: ") + msg);
    if (st != RT_OK) throw UserError(std::string("--motion: ") + msg, 2);
    m_frame.reset(rt_scene_clone(m_scene.get()));
    if (!m_frame) throw UserError("--motion: out of memory copying the scene");
    m_moved.assign(rt_scene_object_count(m_scene.get()), 0);
    if (quiet) return;
    for (size_t i = 0; i < rt_motion_entry_count(m_motion.get()); i++) {
        char line[RT_MSG_LEN];
        rt_motion_describe(m_motion.get(), m_scene.get(), i, line, sizeof line);
        std::fprintf(stderr, "motion: %s\n", line);
    }
}

void SceneMotion::move_objects(uint32_t k)
{
    char msg[RT_MSG_LEN] = "";
    if (rt_motion_apply(m_motion.get(), m_scene.get(), m_frame.get(), k, m_moved.data(), msg, sizeof msg) != RT_OK)
        throw UserError(std::string("--motion: ") + msg, 2);
}

MotionFrameCost SceneMotion::move_to(uint32_t k, GridPtr &grid, const int cells[3], rt_preprocess_count rule,
                                     rt_budget *budget)
{
    move_objects(k);
    if (k > 0 && grid) return update_lists(k, grid.get(), budget);
    char msg[RT_MSG_LEN] = "";
    MotionFrameCost cost;
    for (uint8_t m : m_moved) cost.objects_moved += m;
    grid.reset();  // the scene's own grid (or the last run's) gives way to the one over every frame
    grid.reset(
        rt_grid_new_in_space(m_frame.get(), cells[0], cells[1], cells[2], &m_space, rule, budget, msg, sizeof msg));
    if (!grid) throw UserError(shown_path(m_path) + ": frame " + std::to_string(k) + ": " + msg);
    cost.update_units = cost.rebuild_units = rt_grid_units_serial(grid.get());
    cost.list_entries = rt_grid_list_entries(grid.get());
    return cost;
}

MotionFrameCost SceneMotion::update_lists(uint32_t k, rt_grid *grid, rt_budget *budget)
{
    char msg[RT_MSG_LEN] = "";
    rt_grid_update_stats st{};
    if (rt_grid_update(grid, m_frame.get(), m_moved.data(), budget, &st, msg, sizeof msg) != RT_OK)
        throw UserError(shown_path(m_path) + ": frame " + std::to_string(k) + ": " + msg);
    MotionFrameCost cost;
    cost.objects_moved = st.objects_moved;
    cost.update_units = st.units;
    cost.rebuild_units = st.rebuild_units;
    cost.list_entries = st.entries;
    return cost;
}

nlohmann::json SceneMotion::json() const
{
    auto vec = [](rt_vec3 v) { return nlohmann::json::array({v.x, v.y, v.z}); };
    nlohmann::json entries = nlohmann::json::array();
    for (size_t i = 0; i < rt_motion_entry_count(m_motion.get()); i++) {
        rt_motion_entry_info e = rt_motion_entry(m_motion.get(), i);
        char line[RT_MSG_LEN];
        rt_motion_describe(m_motion.get(), m_scene.get(), i, line, sizeof line);
        entries.push_back(
            {{"line", e.line}, {"first", e.first}, {"last", e.last}, {"keys", e.keys}, {"matched", line}});
    }
    nlohmann::json space = nullptr;
    if (m_space.lo.x <= m_space.hi.x) space = {{"lo", vec(m_space.lo)}, {"hi", vec(m_space.hi)}};
    return {{"file", m_path}, {"frames", frame_count()}, {"entries", entries}, {"object_space", space}};
}

nlohmann::json motion_frame_json(const MotionFrameCost &cost)
{
    return {{"objects_moved", cost.objects_moved},
            {"update_units", cost.update_units},
            {"rebuild_units", cost.rebuild_units},
            {"list_entries", cost.list_entries}};
}

}  // namespace torusrt
