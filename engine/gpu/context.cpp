#include "engine/gpu/context.h"

#include <vulkan/vulkan.h>

#include <array>
#include <string>

#include "engine/gpu/command_list.h"
#include "engine/gpu/debug_utils.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/instance.h"
#include "engine/gpu/memory.h"
#include "engine/gpu/vk_check.h"

namespace mvpl::gpu {
namespace {

// Sizes of the per-submission descriptor pool: far more than one submission of the planned
// passes uses; running out is reported, not worked around.
constexpr uint32_t kTransientSets = 1024;
constexpr uint32_t kTransientDescriptorsPerType = 4096;

void full_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
    VkMemoryBarrier2 barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2;
    barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    barrier.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
    barrier.dstStageMask = dst_stage;
    barrier.dstAccessMask = dst_access;
    VkDependencyInfo dependency{};
    dependency.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO;
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

// Who asked for the validation layer ("" where nobody did), for its log.
std::string validation_source(const ContextOptions& options) {
    if (options.validation) return "the caller (ContextOptions::validation)";
    if (validation_requested_by_environment()) return "MVPL_VALIDATION=1";
    return "";
}

// The index of the device to use: `requested`, or the default one when negative.
int pick_device(const std::vector<DeviceInfo>& devices, int requested) {
    if (devices.empty()) throw GpuError("the Vulkan loader lists no device");
    int index = requested;
    if (index < 0) {
        index = default_device_index(devices);
        if (index < 0) {
            throw GpuError("no usable Vulkan device: device 0 (" + devices[0].name + ") has " +
                           devices[0].unusable_reason());
        }
    } else if (index >= int(devices.size())) {
        throw GpuError("no Vulkan device " + std::to_string(index) + " (there are " +
                       std::to_string(devices.size()) + "; see `mvpl info`)");
    } else if (!devices[size_t(index)].usable()) {
        throw GpuError("Vulkan device " + std::to_string(index) + " (" +
                       devices[size_t(index)].name +
                       ") is not usable: " + devices[size_t(index)].unusable_reason());
    }
    return index;
}

// The optional core features mvpl turns on where the device has them.
VkPhysicalDeviceFeatures optional_core_features(const VkPhysicalDeviceFeatures& has) {
    VkPhysicalDeviceFeatures core{};
    core.imageCubeArray = has.imageCubeArray;  // the shadow cube-map array
    core.independentBlend = has.independentBlend;
    core.depthClamp = has.depthClamp;
    core.samplerAnisotropy = has.samplerAnisotropy;
    core.fragmentStoresAndAtomics = has.fragmentStoresAndAtomics;
    core.shaderStorageImageReadWithoutFormat = has.shaderStorageImageReadWithoutFormat;
    core.shaderStorageImageWriteWithoutFormat = has.shaderStorageImageWriteWithoutFormat;
    // The shadow maps' rg32f (engine/render/shadow_texel.h); DeviceInfo::unusable_reason needs it.
    core.shaderStorageImageExtendedFormats = has.shaderStorageImageExtendedFormats;
    core.multiDrawIndirect = has.multiDrawIndirect;
    core.drawIndirectFirstInstance = has.drawIndirectFirstInstance;
    return core;
}

}  // namespace

Context::Context(ContextOptions options)
    : m_log(options.validation_log ? options.validation_log : std::make_shared<ValidationLog>()) {
    m_options = options;
    m_options.validation_log = m_log;
    m_instance = std::make_unique<Instance>(validation_source(options), m_log.get(),
                                            options.instance_extensions);

    const std::vector<VkPhysicalDevice> physical = m_instance->physical_devices();
    std::vector<DeviceInfo> devices;
    for (size_t i = 0; i < physical.size(); ++i)
        devices.push_back(describe_device(physical[i], int(i)));
    const int index = pick_device(devices, options.device_index);
    m_options.device_index = index;
    m_device_info = devices[size_t(index)];
    m_physical_device = physical[size_t(index)];
    m_queue_family = uint32_t(m_device_info.queue_family);
    if (options.can_present) {
        if (!options.can_present(m_instance->handle(), m_physical_device, m_queue_family)) {
            throw GpuError(m_device_info.name + ": its graphics+compute queue family " +
                           std::to_string(m_queue_family) + " cannot present to the window system");
        }
        m_presentable = true;
    }
    create_device();
    try {
        vkGetDeviceQueue(m_device, m_queue_family, 0, &m_queue);
        m_allocator = std::make_unique<MemoryAllocator>(m_physical_device, m_device);
        create_submission_objects();
    } catch (...) {
        destroy();
        throw;
    }
    set_debug_name(VK_OBJECT_TYPE_COMMAND_BUFFER, uint64_t(m_command_buffer), "submit_and_wait");
}

void Context::create_device() {
    // What the device offers, then the subset mvpl turns on: required ones are checked, optional
    // ones are enabled when present so that the passes can rely on a fixed baseline on desktops.
    VkPhysicalDeviceVulkan13Features has13{};
    has13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
    VkPhysicalDeviceVulkan12Features has12{};
    has12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
    has12.pNext = &has13;
    VkPhysicalDeviceFeatures2 has{};
    has.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    has.pNext = &has12;
    vkGetPhysicalDeviceFeatures2(m_physical_device, &has);
    if (!has13.synchronization2 || !has13.dynamicRendering || !has12.hostQueryReset) {
        throw GpuError(m_device_info.name +
                       " lacks synchronization2, dynamicRendering or hostQueryReset");
    }

    VkPhysicalDeviceVulkan13Features use13{};
    use13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
    use13.synchronization2 = VK_TRUE;
    use13.dynamicRendering = VK_TRUE;
    use13.maintenance4 = has13.maintenance4;
    VkPhysicalDeviceVulkan12Features use12{};
    use12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
    use12.pNext = &use13;
    use12.hostQueryReset = VK_TRUE;  // GpuTimer resets its queries from the host
    use12.scalarBlockLayout = has12.scalarBlockLayout;
    use12.timelineSemaphore = has12.timelineSemaphore;
    VkPhysicalDeviceFeatures2 use{};
    use.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    use.pNext = &use12;
    use.features = optional_core_features(has.features);

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_info{};
    queue_info.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queue_info.queueFamilyIndex = m_queue_family;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;
    VkDeviceCreateInfo device_info{};
    device_info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    device_info.pNext = &use;
    device_info.queueCreateInfoCount = 1;
    device_info.pQueueCreateInfos = &queue_info;
    const char* swapchain_extension = VK_KHR_SWAPCHAIN_EXTENSION_NAME;
    if (m_presentable) {
        device_info.enabledExtensionCount = 1;
        device_info.ppEnabledExtensionNames = &swapchain_extension;
    }
    vk_check(vkCreateDevice(m_physical_device, &device_info, nullptr, &m_device),
             "vkCreateDevice(" + m_device_info.name + ")");
}

void Context::create_submission_objects() {
    VkCommandPoolCreateInfo pool_info{};
    pool_info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool_info.queueFamilyIndex = m_queue_family;
    vk_check(vkCreateCommandPool(m_device, &pool_info, nullptr, &m_command_pool),
             "vkCreateCommandPool");
    VkCommandBufferAllocateInfo cmd_info{};
    cmd_info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    cmd_info.commandPool = m_command_pool;
    cmd_info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cmd_info.commandBufferCount = 1;
    vk_check(vkAllocateCommandBuffers(m_device, &cmd_info, &m_command_buffer),
             "vkAllocateCommandBuffers");
    VkFenceCreateInfo fence_info{};
    fence_info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    vk_check(vkCreateFence(m_device, &fence_info, nullptr, &m_fence), "vkCreateFence");

    const std::array<VkDescriptorPoolSize, 4> sizes{{
        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kTransientDescriptorsPerType},
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kTransientDescriptorsPerType},
        {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kTransientDescriptorsPerType},
        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kTransientDescriptorsPerType},
    }};
    VkDescriptorPoolCreateInfo descriptor_info{};
    descriptor_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    descriptor_info.maxSets = kTransientSets;
    descriptor_info.poolSizeCount = uint32_t(sizes.size());
    descriptor_info.pPoolSizes = sizes.data();
    vk_check(vkCreateDescriptorPool(m_device, &descriptor_info, nullptr, &m_transient_pool),
             "vkCreateDescriptorPool");
}

Context::~Context() {
    destroy();
}

void Context::destroy() noexcept {
    if (m_device) {
        vkDeviceWaitIdle(m_device);
        if (m_transient_pool) vkDestroyDescriptorPool(m_device, m_transient_pool, nullptr);
        if (m_fence) vkDestroyFence(m_device, m_fence, nullptr);
        if (m_command_pool) vkDestroyCommandPool(m_device, m_command_pool, nullptr);
        if (m_allocator && m_allocator->allocation_count() > 0) {
            // The validation layer reports leaked VkDeviceMemory only by handle; this says how
            // much.
            m_log->add("[mvpl error] " + std::to_string(m_allocator->allocation_count()) +
                       " device memory allocations (" +
                       std::to_string(m_allocator->allocated_bytes()) +
                       " bytes) outlive their Context");
        }
        m_allocator.reset();
        vkDestroyDevice(m_device, nullptr);
        m_device = nullptr;
    }
    m_instance.reset();
}

bool Context::validation_enabled() const {
    return m_instance->validation();
}

VkInstance Context::instance() const {
    return m_instance->handle();
}

const DebugUtils* Context::debug_utils() const {
    return m_instance->debug_utils();
}

void Context::set_debug_name(int object_type, uint64_t handle, std::string_view name) const {
    if (const DebugUtils* utils = debug_utils()) {
        utils->set_name(m_device, VkObjectType(object_type), handle, name);
    }
}

void Context::wait_idle() const {
    vk_check(vkDeviceWaitIdle(m_device), "vkDeviceWaitIdle");
}

VkDescriptorSet Context::allocate_transient_set(VkDescriptorSetLayout layout) {
    VkDescriptorSetAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    info.descriptorPool = m_transient_pool;
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    const VkResult result = vkAllocateDescriptorSets(m_device, &info, &set);
    if (result == VK_ERROR_OUT_OF_POOL_MEMORY || result == VK_ERROR_FRAGMENTED_POOL) {
        throw GpuError("more than " + std::to_string(kTransientSets) +
                       " descriptor sets (or their descriptors) in one submit_and_wait; split it");
    }
    vk_check(result, "vkAllocateDescriptorSets");
    return set;
}

void Context::submit_and_wait(const std::function<void(CommandList&)>& record) {
    if (m_recording_thread.load() == std::this_thread::get_id()) {
        // The mutex below would deadlock: say what happened instead.
        throw GpuError(
            "submit_and_wait called while recording (an upload, download or Image "
            "creation inside a submit_and_wait callback?)");
    }
    std::lock_guard lock(m_submit_mutex);
    // Leaves the pool empty whichever way this returns, so a failed recording does not leak sets.
    struct PoolReset {
        VkDevice device;
        VkDescriptorPool pool;
        ~PoolReset() { vkResetDescriptorPool(device, pool, 0); }
    } pool_reset{m_device, m_transient_pool};

    vk_check(vkResetCommandBuffer(m_command_buffer, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vk_check(vkBeginCommandBuffer(m_command_buffer, &begin), "vkBeginCommandBuffer");
    // Earlier submissions' writes → anything here. Host writes before the submit need nothing:
    // vkQueueSubmit makes them visible.
    full_barrier(m_command_buffer, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                 VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
    CommandList list(*this, m_command_buffer);
    struct Recording {
        std::atomic<std::thread::id>& thread;
        explicit Recording(std::atomic<std::thread::id>& t) : thread(t) {
            thread = std::this_thread::get_id();
        }
        ~Recording() { thread = std::thread::id(); }
    };
    {
        const Recording recording(m_recording_thread);
        record(list);
    }
    // Everything written → the host, which reads mapped memory after the fence.
    full_barrier(m_command_buffer, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    vk_check(vkEndCommandBuffer(m_command_buffer), "vkEndCommandBuffer");

    VkCommandBufferSubmitInfo cmd_info{};
    cmd_info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO;
    cmd_info.commandBuffer = m_command_buffer;
    VkSubmitInfo2 submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2;
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &cmd_info;
    vk_check(vkQueueSubmit2(m_queue, 1, &submit, m_fence), "vkQueueSubmit2");
    vk_check(vkWaitForFences(m_device, 1, &m_fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    vk_check(vkResetFences(m_device, 1, &m_fence), "vkResetFences");
}

}  // namespace mvpl::gpu
