#pragma once
// What mvpl.load_file returns: a scene file with its -D and -a options, loaded once with the
// default camera and environment (so that a bad file is refused by load_file) and loaded again
// only by a render that asks for another camera or environment.
#include <memory>
#include <string>
#include <vector>

#include "tools/cli/arg_parser.h"
#include "tools/session/scene_session.h"

namespace mvpl::python {

class SceneHandle {
public:
    // `load_tokens`: -D NAME=VALUE and -a PATH, as the command line takes them. Throws as the
    // command line's loading does (InputError, UsageError).
    SceneHandle(std::string path, std::vector<std::string> load_tokens);

    const std::string& path() const { return m_path; }
    // SCENE and the load options, the start of a command line for render or reference.
    std::vector<std::string> command_line() const;
    // The scene as `parser` (parsed) asks for it: the one loaded, unless it was given a camera
    // or environment option, which is then loaded with `camera` and `environment`.
    std::shared_ptr<const session::SceneSession> session_for(
        const cli::ArgParser& parser, const scene::CameraChoice& camera,
        const session::EnvironmentChoice& environment) const;

private:
    std::string m_path;
    std::vector<std::string> m_load_tokens;
    scene::LoadOptions m_load;
    std::shared_ptr<const session::SceneSession> m_session;
};

}  // namespace mvpl::python
