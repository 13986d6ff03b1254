// PreviewApp's scene replaced while it runs: a dropped scene file, a dropped environment map or
// a changed environment setting. What cannot be read leaves everything as it was.
#include <cstdio>
#include <filesystem>

#include "engine/core/error.h"
#include "engine/core/file_extension.h"
#include "tools/preview/app.h"

namespace mvpl::preview {

void PreviewApp::report(const std::string& message) {
    std::fprintf(stderr, "mvpl: error: %s\n", message.c_str());
    m_message = message;
    m_hud_dirty = true;
}

void PreviewApp::drop(const std::string& path) {
    const std::string extension = lower_extension(path);
    if (extension == ".hdr" || extension == ".exr") {
        scene::EnvironmentChoice environment = m_environment;
        environment.map = path;
        set_environment(environment);
        return;
    }
    try {
        load_scene(path, m_environment, false);
    } catch (const InputError& e) {
        report(e.what());
    } catch (const UsageError& e) {
        report(e.what());
    }
}

void PreviewApp::set_environment(const scene::EnvironmentChoice& environment) {
    try {
        load_scene(m_session->path(), environment, true);
    } catch (const InputError& e) {
        report(e.what());
    } catch (const UsageError& e) {
        report(e.what());
    }
}

void PreviewApp::load_scene(const std::string& path, const scene::EnvironmentChoice& environment,
                            bool keep_camera) {
    // The command line's camera for the scene it named; a dropped one's own first camera.
    auto session = std::make_unique<session::SceneSession>(
        path, keep_camera ? m_options.camera : scene::CameraChoice{}, environment, m_options.load);
    // Nothing reads the old scene from here on; its renderer goes once the GPU is done with it.
    m_context.wait_idle();
    m_replay = nullptr;
    m_history = nullptr;
    m_chain.reset();
    m_mc_history.reset();
    m_integrator.reset();
    m_session = std::move(session);
    m_environment = environment;
    m_integrator = make_integrator();
    if (!keep_camera) {
        m_controller = CameraController(m_session->camera(), m_session->scene().bounds());
        m_window.set_title("mvpl preview: " + std::filesystem::path(path).filename().string());
    }
    m_message.clear();
    m_moved = true;
    m_hud_dirty = true;
}

}  // namespace mvpl::preview
