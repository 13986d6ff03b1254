#pragma once
// The headless Vulkan 1.3 context: instance, one physical device, one graphics+compute queue,
// a command pool and a "record, submit and wait" helper. Everything on the GPU belongs to one
// Context, which must outlive the buffers, images, pipelines and timers made with it.
//
// Vulkan-free to include; the handle accessors return opaque types that only code including
// <vulkan/vulkan.h> (engine/gpu, engine/render) can use.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "engine/gpu/device_info.h"
#include "engine/gpu/validation.h"
#include "engine/gpu/vk_fwd.h"

namespace mvpl::gpu {

class CommandList;
class DebugUtils;
class Instance;
class MemoryAllocator;

struct ContextOptions {
    // Index into enumerate_devices() (`--device N`); -1: default_device_index().
    int device_index = -1;
    // Load VK_LAYER_KHRONOS_validation and log its warnings and errors. Also switched on by
    // MVPL_VALIDATION=1. A missing layer is an error, never silently skipped.
    bool validation = false;
    // Where validation messages go. Pass your own to see what is reported while the context is
    // destroyed (leaked objects); by default the context makes one.
    std::shared_ptr<ValidationLog> validation_log;
    // Presenting to a window (mvpl preview); both empty for the headless context. The instance
    // extensions the window system needs (glfwGetRequiredInstanceExtensions), and a test whether
    // a queue family of a physical device can present to it (glfwGetPhysicalDevicePresentation-
    // Support). When can_present is set the device gets VK_KHR_swapchain, and a device whose
    // graphics+compute queue cannot present is an error: one queue does everything.
    std::vector<std::string> instance_extensions;
    std::function<bool(VkInstance, VkPhysicalDevice, uint32_t queue_family)> can_present;
};

class Context {
public:
    explicit Context(ContextOptions options = {});
    ~Context();
    // Resources keep a pointer to their context: it never moves.
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    const DeviceInfo& device_info() const { return m_device_info; }
    // What it was made with, its validation log included: a second context made from them is
    // another logical device on the same physical device, logging to the same place
    // (render::VplRenderer's `devices`).
    const ContextOptions& options() const { return m_options; }

    bool validation_enabled() const;
    // Whether the device was created with VK_KHR_swapchain (ContextOptions::can_present).
    bool presentable() const { return m_presentable; }
    size_t validation_message_count() const { return m_log->count(); }
    std::vector<std::string> validation_messages() const { return m_log->messages(); }
    ValidationLog& validation_log() const { return *m_log; }

    // Records commands with record(), submits them and blocks until the GPU is done. All
    // earlier GPU writes are visible to the recorded commands, and all their writes are visible
    // to the host afterwards (mapped buffers can be read right away). Descriptor sets that the
    // commands allocated are freed on return. Thread-safe (submissions are serialised); calling
    // it from inside record() (an upload, download or Image creation there) throws GpuError.
    void submit_and_wait(const std::function<void(CommandList&)>& record);
    void wait_idle() const;

    MemoryAllocator& allocator() { return *m_allocator; }

    // For engine/gpu and the render passes.
    VkInstance instance() const;
    VkPhysicalDevice physical_device() const { return m_physical_device; }
    VkDevice device() const { return m_device; }
    VkQueue queue() const { return m_queue; }
    uint32_t queue_family() const { return m_queue_family; }
    // VK_EXT_debug_utils with validation on, otherwise nullptr.
    const DebugUtils* debug_utils() const;
    // Names an object for validation messages (a no-op without validation). object_type is a
    // VkObjectType; handle the object cast to uint64_t.
    void set_debug_name(int object_type, uint64_t handle, std::string_view name) const;
    // A descriptor set from the pool that submit_and_wait resets after its wait; only valid
    // inside a submit_and_wait recording.
    VkDescriptorSet allocate_transient_set(VkDescriptorSetLayout layout);

private:
    // The logical device on m_physical_device with the features mvpl uses (and the swapchain
    // extension when presentable).
    void create_device();
    // The command pool and buffer, fence and transient descriptor pool of submit_and_wait.
    void create_submission_objects();
    void destroy() noexcept;

    std::shared_ptr<ValidationLog> m_log;
    ContextOptions m_options;
    std::unique_ptr<Instance> m_instance;
    DeviceInfo m_device_info;
    VkPhysicalDevice m_physical_device = nullptr;
    VkDevice m_device = nullptr;
    VkQueue m_queue = nullptr;
    uint32_t m_queue_family = 0;
    bool m_presentable = false;
    std::unique_ptr<MemoryAllocator> m_allocator;

    std::mutex m_submit_mutex;
    std::atomic<std::thread::id> m_recording_thread;  // the thread inside record(), if any
    VkCommandPool m_command_pool = nullptr;
    VkCommandBuffer m_command_buffer = nullptr;
    VkFence m_fence = nullptr;
    VkDescriptorPool m_transient_pool = nullptr;
};

}  // namespace mvpl::gpu
