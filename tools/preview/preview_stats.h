#pragma once
// What the preview measures: time to the first image, frame times (separately while the camera
// moves, the interactive case), VPLs per second; and the HUD's lines of text.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace mvpl::preview {

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

    std::vector<std::string> hud_lines(const std::string& sampler, bool chain, uint32_t width,
                                       uint32_t height, size_t vpls, uint64_t work, float clamp,
                                       float exposure, const std::string& statistics,
                                       bool converged) const;
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
