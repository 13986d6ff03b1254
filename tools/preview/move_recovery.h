#pragma once
// How the picture recovers after a camera move: the VPLs the resting sum held when the move
// began, the share of them the first frame at rest holds again, and the time from that frame
// until a sum at rest holds kRecoveredShare of them (the preview replays its kept VPLs after a
// move: vpl_history.h; with kept shadow cubes their shadow pass is a copy).
#include <cstdint>
#include <string>
#include <vector>

namespace mvpl::preview {

class MoveRecovery {
public:
    static constexpr double kRecoveredShare = 0.9;

    // Once a frame, after shading: whether the camera moved this frame, the VPLs in the sum, and
    // when the frame began and ended (seconds since the start).
    void frame(bool moving, uint64_t sum_vpls, double began, double ended);
    // "" before the first move that came to rest.
    std::string summary() const;

private:
    uint64_t m_resting_vpls = 0;  // the sum at rest in the last frame before a move
    uint64_t m_target = 0;        // of the move being recovered from (0: none)
    bool m_moving = false;
    double m_rest_start = 0.0;          // the first frame at rest after the move began
    std::vector<double> m_first_share;  // per move: first frame at rest / resting VPLs before
    std::vector<double> m_recovery;     // per recovered move: from its beginning to the share
};

}  // namespace mvpl::preview
