#include "python/scene_handle.h"

#include "tools/cli/option_groups.h"

namespace mvpl::python {

namespace {

// Whether `parser` saw any camera or environment option (read from their option table, so that
// no name is written twice).
bool asks_for_another_view(const cli::ArgParser& parser) {
    cli::ArgParser view("render", "");
    cli::CameraArgs camera;
    cli::add_camera_options(view, camera);
    cli::EnvironmentArgs environment;
    cli::add_environment_options(view, environment);
    for (const cli::ArgParser::OptionInfo& o : view.options())
        if (parser.given(o.name)) return true;
    return false;
}

}  // namespace

SceneHandle::SceneHandle(std::string path, std::vector<std::string> load_tokens)
    : m_path(std::move(path)), m_load_tokens(std::move(load_tokens)) {
    cli::ArgParser parser("load_file", "");
    cli::SceneFileArgs scene_file;
    cli::add_scene_file_options(parser, scene_file);
    parser.parse(m_load_tokens);
    m_load = scene_file.options;
    m_session = std::make_shared<const session::SceneSession>(m_path, scene::CameraChoice{},
                                                              session::EnvironmentChoice{}, m_load);
}

std::vector<std::string> SceneHandle::command_line() const {
    std::vector<std::string> line{m_path};
    line.insert(line.end(), m_load_tokens.begin(), m_load_tokens.end());
    return line;
}

std::shared_ptr<const session::SceneSession> SceneHandle::session_for(
    const cli::ArgParser& parser, const scene::CameraChoice& camera,
    const session::EnvironmentChoice& environment) const {
    if (!asks_for_another_view(parser)) return m_session;
    return std::make_shared<const session::SceneSession>(m_path, camera, environment, m_load);
}

}  // namespace mvpl::python
