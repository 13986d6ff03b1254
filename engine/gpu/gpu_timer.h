#pragma once
// GPU time per labelled pass from timestamp queries: begin/end around the commands of a pass
// while recording, read the milliseconds after the submission has finished. Vulkan-free.
//
//   GpuTimer timer(context);
//   context.submit_and_wait([&](CommandList& cmd) {
//       const auto scope = timer.begin(cmd, "shadow");  …  timer.end(cmd, scope);
//   });
//   timer.milliseconds("shadow");
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "engine/gpu/vk_fwd.h"

namespace mvpl::gpu {

class CommandList;
class Context;

struct PassTime {
    std::string label;
    double milliseconds = 0.0;
};

class GpuTimer {
public:
    // Room for max_scopes begin/end pairs between resets.
    explicit GpuTimer(Context& context, uint32_t max_scopes = 64);
    ~GpuTimer();
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    // False when the queue has no timestamps (timestampValidBits 0); every time reads 0 then.
    bool supported() const { return m_valid_mask != 0; }

    // Forgets all scopes (host-side query reset: never while a submission using them runs).
    void reset();
    // Writes the start timestamp after all earlier commands; returns the scope for end().
    uint32_t begin(CommandList& cmd, std::string_view label);
    // Writes the end timestamp once the scope's commands are done.
    void end(CommandList& cmd, uint32_t scope);

    // Every ended scope, in begin order. Call after the submission finished (it waits for the
    // results otherwise).
    std::vector<PassTime> results() const;
    // Sum over the scopes with this label (a pass timed in several submissions).
    double milliseconds(std::string_view label) const;

private:
    Context* m_context;
    VkQueryPool m_pool = nullptr;
    uint32_t m_capacity = 0;
    uint64_t m_valid_mask = 0;
    double m_ns_per_tick = 0.0;
    std::vector<std::string> m_labels;
    std::vector<bool> m_ended;
};

}  // namespace mvpl::gpu
