#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "engine/gpu/context.h"
#include "engine/gpu/device_info.h"
#include "engine/gpu/gpu_error.h"
#include "tests/gpu/gpu_test.h"

namespace mvpl::gpu {
namespace {

using testing::GpuTest;

// Sets an environment variable for one scope and restores it afterwards.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : m_name(name) {
        if (const char* old = std::getenv(name)) m_old = old;
        ::setenv(name, value, 1);
    }
    ~ScopedEnv() {
        if (m_old)
            ::setenv(m_name, m_old->c_str(), 1);
        else
            ::unsetenv(m_name);
    }

private:
    const char* m_name;
    std::optional<std::string> m_old;
};

using ContextTest = GpuTest;

TEST_F(ContextTest, CreatesAValidatedContextOnTheDefaultDevice) {
    EXPECT_TRUE(context().validation_enabled());
    const DeviceInfo& device = context().device_info();
    EXPECT_TRUE(device.usable()) << device.unusable_reason();
    EXPECT_FALSE(device.name.empty());
    EXPECT_GE(device.queue_family, 0);
    EXPECT_GT(device.limits.timestamp_period, 0.0f);
    EXPECT_GT(device.timestamp_valid_bits, 0u);
    EXPECT_TRUE(device.image_cube_array);
    EXPECT_TRUE(device.storage_image_extended_formats);
    EXPECT_NE(context().device(), nullptr);
    EXPECT_NE(context().queue(), nullptr);
}

TEST_F(ContextTest, DefaultDeviceIsTheOneEnumerationPicks) {
    const std::vector<DeviceInfo> devices = enumerate_devices();
    ASSERT_FALSE(devices.empty());
    for (size_t i = 0; i < devices.size(); ++i)
        EXPECT_EQ(devices[i].index, int(i));
    EXPECT_EQ(default_device_index(devices), context().device_info().index);
    EXPECT_EQ(devices[size_t(context().device_info().index)].name, context().device_info().name);
}

TEST_F(ContextTest, DefaultPrefersDiscreteThenIntegratedGpus) {
    std::vector<DeviceInfo> devices(3);
    for (int i = 0; i < 3; ++i) {
        devices[size_t(i)].index = i;
        devices[size_t(i)].api_version = (1u << 22) | (3u << 12);  // 1.3.0
        devices[size_t(i)].queue_family = 0;
        devices[size_t(i)].storage_image_extended_formats = true;
    }
    devices[0].type = DeviceType::cpu;
    devices[1].type = DeviceType::integrated_gpu;
    devices[2].type = DeviceType::discrete_gpu;
    EXPECT_EQ(default_device_index(devices), 2);
    devices[2].api_version = (1u << 22) | (2u << 12);  // a Vulkan 1.2 GPU is skipped
    EXPECT_EQ(default_device_index(devices), 1);
    devices[1].queue_family = -1;
    EXPECT_EQ(default_device_index(devices), 0);
    devices[0].queue_family = -1;
    EXPECT_EQ(default_device_index(devices), -1);
}

TEST_F(ContextTest, AskingForADeviceThatDoesNotExistIsAnError) {
    ContextOptions options;
    options.device_index = 99;
    try {
        Context bad(options);
        ADD_FAILURE() << "no exception";
    } catch (const GpuError& e) {
        EXPECT_NE(std::string(e.what()).find("no Vulkan device 99"), std::string::npos) << e.what();
    }
}

TEST_F(ContextTest, MissingLayerRequestedByTheEnvironmentIsAClearError) {
    // VK_LAYER_PATH replaces the loader's search path for explicit layers: no layer is found.
    const ScopedEnv layer_path("VK_LAYER_PATH", "/nonexistent/mvpl-test-layers");
    const ScopedEnv request("MVPL_VALIDATION", "1");
    EXPECT_TRUE(validation_requested_by_environment());
    EXPECT_FALSE(validation_layer_available());
    try {
        Context unvalidated;
        ADD_FAILURE() << "no exception";
    } catch (const GpuError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("MVPL_VALIDATION=1"), std::string::npos) << message;
        EXPECT_NE(message.find(kValidationLayerName), std::string::npos) << message;
    }
}

TEST_F(ContextTest, ValidationFromTheEnvironmentOnly) {
    const ScopedEnv request("MVPL_VALIDATION", "1");
    auto log = std::make_shared<ValidationLog>();
    ContextOptions options;
    options.validation_log = log;
    {
        const Context from_env(options);
        EXPECT_TRUE(from_env.validation_enabled());
    }
    EXPECT_EQ(log->count(), 0u) << log->summary();
}

}  // namespace
}  // namespace mvpl::gpu
