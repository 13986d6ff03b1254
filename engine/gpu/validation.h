#pragma once
// Vulkan validation: whether it is wanted, and the log that collects what the layer says.
// Vulkan-free, so that tests and tools can assert on it.
#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

namespace mvpl::gpu {

inline constexpr const char* kValidationLayerName = "VK_LAYER_KHRONOS_validation";

// True when MVPL_VALIDATION is set to 1 (also "true"/"on"/"yes").
bool validation_requested_by_environment();

// Whether the Khronos validation layer is installed (asks the Vulkan loader).
bool validation_layer_available();

// Warnings and errors from the validation layer (and the loader), one formatted line each:
// "[validation error] VUID-…: text". Thread-safe: the layer may call from driver threads.
class ValidationLog {
public:
    void add(std::string message);
    size_t count() const;
    std::vector<std::string> messages() const;
    void clear();
    // The first max_messages messages, one per line, for a test failure or an error report.
    std::string summary(size_t max_messages = 8) const;

private:
    mutable std::mutex m_mutex;
    std::vector<std::string> m_messages;
};

}  // namespace mvpl::gpu
