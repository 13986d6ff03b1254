#pragma once
// What the preview measures: time to the first image, frame times (separately while the camera
// moves, the interactive case), VPLs per second; and the HUD's lines of text.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace mvpl::preview {

// Which parts of the estimator (the one `mvpl render` runs) the current sum has on, for the HUD.
struct EstimatorParts {
    float clamp = 0.0f;         // × the scene diagonal; 0: not clamped
    bool compensation = false;  // the clamped light added back (CPU passes, at rest)
    bool caustics = false;      // the caustic tracer runs (at rest, where the scene has them)
    bool chains = false;        // specular chains traced (the scene has surfaces they continue)
    float vsl_radius = 0.0f;    // 0: point VPLs
    bool moving = false;        // a moving frame's sum: the CPU passes wait for the camera
    // Row-column sampling: VPLs a pool and clusters a full pool (pool 0: every VPL shaded).
    uint32_t pool = 0, clusters = 0;
};

// What the HUD says of the current sum.
struct HudState {
    std::string sampler;
    bool chain = false;  // a Metropolis chain's units (steps), not light paths
    uint32_t width = 0, height = 0;
    size_t vpls = 0;
    uint64_t work = 0;
    double seconds = 0.0;  // since the sum began (the last restart)
    float exposure = 0.0f;
    std::string statistics;  // the sampler's
    bool converged = false;
    EstimatorParts parts;
};

class PreviewStats {
public:
    void add_vpls(size_t count);
    // seconds: this frame, from its start to the end of its present; since_start: since the
    // command started; moving: the sum restarted this frame (camera move or resize).
    void frame_presented(double seconds, double since_start, bool moving);
    // Where a moving frame's time went: restarting the sum (the G-buffer), shading VPLs,
    // presenting (tonemap, blit, present and its wait).
    void moving_phases(double restart, double shading, double present);

    // VPLs shaded in the last second (all of them until one second has passed).
    double vpls_per_second() const;
    double last_frame_ms() const { return m_last_ms; }

    std::vector<std::string> hud_lines(const HudState& state) const;
    // One line for the end of a run.
    std::string summary() const;

private:
    struct Sample {
        double time;  // since the first frame
        size_t vpls;
    };
    std::deque<Sample> m_recent;
    double m_clock = 0.0;  // since_start of the last frame
    size_t m_pending_vpls = 0;
    size_t m_total_vpls = 0;
    double m_first_image = -1.0;
    double m_last_ms = 0.0;
    uint64_t m_frames = 0;
    double m_frame_seconds = 0.0;
    uint64_t m_moving_frames = 0;
    double m_moving_seconds = 0.0;
    double m_moving_worst = 0.0;
    double m_moving_restart = 0.0;
    double m_moving_shading = 0.0;
    double m_moving_present = 0.0;
};

}  // namespace mvpl::preview
