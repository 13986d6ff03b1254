#pragma once
// The scene as every `mvpl` command that renders it needs it — loaded, its Embree BVH built, its
// lights prepared for sampling, and the camera it is seen from — built in one place for the
// command line (tools/cli) and the preview window (tools/preview), as pbrt-v4's cmd/ tools share
// one scene set-up.
#include <string>

#include "engine/core/image.h"
#include "engine/core/timer.h"
#include "engine/integrator/scene_view.h"
#include "engine/light/light_sampler.h"
#include "engine/scene/camera_choice.h"
#include "engine/scene/environment_choice.h"
#include "engine/scene/scene.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"

namespace mvpl::session {

using scene::EnvironmentChoice;

class SceneSession {
public:
    // Throws InputError (exit code 2) when the scene cannot be read, UsageError when `camera`
    // names no camera of it. Prints the loader's warnings (Scene::warnings).
    explicit SceneSession(const std::string& path, const scene::CameraChoice& camera = {},
                          const EnvironmentChoice& environment = {},
                          const scene::LoadOptions& load = {});
    SceneSession(const SceneSession&) = delete;
    SceneSession& operator=(const SceneSession&) = delete;

    const std::string& path() const { return m_path; }
    const scene::Scene& scene() const { return m_scene; }
    const trace::Accel& accel() const { return m_accel; }
    const light::LightSampler& lights() const { return m_lights; }
    // The scene's own camera (the one in the file, or one framing a bare mesh).
    const scene::Camera& camera() const { return m_scene.camera; }
    // What an estimate needs of it, seen from `camera` (default: camera()).
    integrator::SceneView view(const scene::Camera* camera = nullptr) const {
        return {&m_scene, &m_accel, &m_lights, camera ? camera : &m_scene.camera};
    }
    // Set-up times (`mvpl bench` reports them apart): loading, the BVH, the lights.
    double load_seconds() const { return m_load_seconds; }
    double bvh_seconds() const { return m_bvh_seconds; }
    double setup_seconds() const { return m_setup_seconds; }

    // Why an image is black, said even under --quiet (a warning is not progress), and at most
    // once a session: the first of these that applies prints "mvpl: warning: PATH: …".
    // Without a light: "the scene has no light; CONSEQUENCE", and returns true.
    bool warn_if_no_light(const std::string& consequence) const;
    // A sampler's finding, e.g. "no light reaches anything the camera sees; the image is black".
    void warn(const std::string& what) const;
    // When every pixel of `image` is 0: warn_if_clipped's line where it applies, otherwise "the
    // image is black: no light reaches what the camera sees".
    void warn_if_black(const Image& image) const;
    // When camera rays (a grid over a width × height image) from the near plane hit nothing and
    // rays from the eye hit something before it: "the image is black: everything the camera sees
    // is nearer than its znear (Z), …"; returns whether that is so.
    bool warn_if_clipped(int width, int height) const;

private:
    // Declaration order is construction order: each stage is timed when it is done.
    std::string m_path;
    Timer m_clock;
    scene::Scene m_scene;
    double m_load_seconds;
    trace::Accel m_accel;
    double m_bvh_seconds;
    light::LightSampler m_lights;
    double m_setup_seconds;
    mutable bool m_warned = false;
};

}  // namespace mvpl::session
