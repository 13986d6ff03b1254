#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include "engine/gpu/buffer.h"
#include "engine/gpu/command_list.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/context.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/gpu_timer.h"
#include "engine/gpu/shader_compiler.h"
#include "tests/gpu/gpu_test.h"

namespace mvpl::gpu {
namespace {

using ComputeTest = testing::GpuTest;

struct SaxpyParams {
    float a;
    uint32_t n;
};

ComputeLayout saxpy_layout() {
    return {{BindingType::storage_buffer, BindingType::storage_buffer}, sizeof(SaxpyParams)};
}

TEST_F(ComputeTest, SaxpyOnTheGpuEqualsTheCpuBitForBit) {
    constexpr uint32_t kCount = 100000;
    constexpr float kA = 1.7f;
    std::mt19937 rng(42);
    std::uniform_real_distribution<float> value(-100.0f, 100.0f);
    std::vector<float> x(kCount);
    std::vector<float> y(kCount);
    for (uint32_t i = 0; i < kCount; ++i) {
        x[i] = value(rng);
        y[i] = value(rng);
    }

    Buffer x_buffer(context(), kCount * sizeof(float), BufferUsage::storage, MemoryLocation::device,
                    "saxpy x");
    Buffer y_buffer(context(), kCount * sizeof(float), BufferUsage::storage, MemoryLocation::device,
                    "saxpy y");
    x_buffer.upload(x);
    y_buffer.upload(y);
    const ComputePipeline pipeline(context(), compile_embedded_shader("test/saxpy.comp"),
                                   saxpy_layout(), "saxpy");
    GpuTimer timer(context());
    const SaxpyParams params{kA, kCount};
    context().submit_and_wait([&](CommandList& cmd) {
        const uint32_t scope = timer.begin(cmd, "saxpy");
        cmd.dispatch(pipeline, {&x_buffer, &y_buffer}, push_bytes(params), (kCount + 255) / 256);
        timer.end(cmd, scope);
    });
    const std::vector<float> result = y_buffer.download<float>(kCount);

    size_t mismatches = 0;
    for (uint32_t i = 0; i < kCount; ++i) {
        // Same operations as the shader's `precise` pair: round after the multiply and the add.
        const float ax = kA * x[i];
        const float expected = ax + y[i];
        if (std::memcmp(&expected, &result[i], sizeof(float)) != 0 && mismatches++ < 5) {
            ADD_FAILURE() << "y[" << i << "] = " << result[i] << ", CPU " << expected;
        }
    }
    EXPECT_EQ(mismatches, 0u);

    ASSERT_TRUE(timer.supported());
    const std::vector<PassTime> times = timer.results();
    ASSERT_EQ(times.size(), 1u);
    EXPECT_EQ(times[0].label, "saxpy");
    EXPECT_GT(times[0].milliseconds, 0.0);
    EXPECT_LT(times[0].milliseconds, 10000.0);
    EXPECT_DOUBLE_EQ(timer.milliseconds("saxpy"), times[0].milliseconds);
}

TEST_F(ComputeTest, TimerSumsScopesWithTheSameLabel) {
    GpuTimer timer(context(), 4);
    Buffer a(context(), 1 << 20, BufferUsage::storage, MemoryLocation::device, "a");
    Buffer b(context(), 1 << 20, BufferUsage::storage, MemoryLocation::device, "b");
    context().submit_and_wait([&](CommandList& cmd) {
        for (int i = 0; i < 2; ++i) {
            const uint32_t scope = timer.begin(cmd, "copy");
            cmd.copy_buffer(a, b, a.size());
            timer.end(cmd, scope);
            cmd.barrier();
        }
        timer.end(cmd, timer.begin(cmd, "other"));
    });
    const std::vector<PassTime> times = timer.results();
    ASSERT_EQ(times.size(), 3u);
    EXPECT_DOUBLE_EQ(timer.milliseconds("copy"), times[0].milliseconds + times[1].milliseconds);
    timer.reset();
    EXPECT_TRUE(timer.results().empty());
    context().submit_and_wait([&](CommandList& cmd) {
        for (int i = 0; i < 4; ++i)
            timer.end(cmd, timer.begin(cmd, "x"));
        EXPECT_THROW(timer.begin(cmd, "one too many"), GpuError);
    });
}

TEST_F(ComputeTest, DeviceBuffersRoundTripAtOffsets) {
    Buffer buffer(context(), 4096, BufferUsage::storage, MemoryLocation::device, "offsets");
    std::vector<uint32_t> values(256);
    for (uint32_t i = 0; i < values.size(); ++i)
        values[i] = i * 2654435761u;
    buffer.upload(values, 1024);
    EXPECT_EQ(buffer.download<uint32_t>(256, 1024), values);
    EXPECT_EQ(buffer.download<uint32_t>(4, 1024 + 8),
              std::vector<uint32_t>(values.begin() + 2, values.begin() + 6));
    EXPECT_THROW(buffer.upload(values, 4096 - 8), GpuError);
}

TEST_F(ComputeTest, HostVisibleBuffersAreMappedAndCopiedOnTheGpu) {
    Buffer upload(context(), 64, BufferUsage::none, MemoryLocation::upload, "upload");
    Buffer readback(context(), 64, BufferUsage::none, MemoryLocation::readback, "readback");
    ASSERT_NE(upload.mapped(), nullptr);
    ASSERT_NE(readback.mapped(), nullptr);
    std::vector<float> values(16);
    for (size_t i = 0; i < values.size(); ++i)
        values[i] = float(i) * 0.5f - 3.0f;
    upload.upload(values);
    context().submit_and_wait([&](CommandList& cmd) { cmd.copy_buffer(upload, readback, 64); });
    EXPECT_EQ(readback.download<float>(16), values);
}

TEST_F(ComputeTest, DispatchChecksItsArgumentsAndAFailedRecordingSubmitsNothing) {
    const ComputePipeline pipeline(context(), compile_embedded_shader("test/saxpy.comp"),
                                   saxpy_layout(), "saxpy");
    Buffer x(context(), 1024, BufferUsage::storage, MemoryLocation::device, "x");
    const SaxpyParams params{1.0f, 256};
    context().submit_and_wait([&](CommandList& cmd) {
        EXPECT_THROW(cmd.dispatch(pipeline, {&x}, push_bytes(params), 1), GpuError);
        const uint32_t too_short = 0;
        EXPECT_THROW(cmd.dispatch(pipeline, {&x, &x}, push_bytes(too_short), 1), GpuError);
    });
    EXPECT_THROW(
        context().submit_and_wait([&](CommandList&) { throw std::runtime_error("abort"); }),
        std::runtime_error);
    // A nested submission (here an upload inside a recording) is an error, not a deadlock.
    EXPECT_THROW(
        context().submit_and_wait([&](CommandList&) { x.upload(std::vector<float>(256, 1.0f)); }),
        GpuError);
    // The context is still usable after the aborted recordings.
    x.upload(std::vector<float>(256, 2.0f));
    EXPECT_EQ(x.download<float>(1)[0], 2.0f);
}

TEST_F(ComputeTest, TheValidationLayerReportsAMisuse) {
    // Proves that the zero-message assertions of the other tests mean something: a buffer without
    // storage usage bound as a storage buffer is reported when the descriptor is written. The
    // recording is then abandoned, so nothing invalid runs.
    const ComputePipeline pipeline(context(), compile_embedded_shader("test/saxpy.comp"),
                                   saxpy_layout(), "saxpy");
    Buffer storage(context(), 1024, BufferUsage::storage, MemoryLocation::device, "storage");
    Buffer not_storage(context(), 1024, BufferUsage::none, MemoryLocation::device, "not storage");
    const SaxpyParams params{1.0f, 256};
    EXPECT_THROW(context().submit_and_wait([&](CommandList& cmd) {
        cmd.dispatch(pipeline, {&storage, &not_storage}, push_bytes(params), 1);
        throw std::runtime_error("abandon");
    }),
                 std::runtime_error);
    EXPECT_GT(context().validation_message_count(), 0u);
    bool named = false;
    for (const std::string& m : context().validation_messages()) {
        named = named || m.find("not storage") != std::string::npos;
    }
    EXPECT_TRUE(named) << context().validation_log().summary();
    context().validation_log().clear();
}

TEST_F(ComputeTest, SynchronisationValidationReportsAMissingBarrier) {
    // Two copies into one buffer need a barrier between them (write after write); without one
    // the layer must complain, or the barriers of the passes go unchecked on lavapipe.
    Buffer a(context(), 256, BufferUsage::none, MemoryLocation::device, "a");
    Buffer b(context(), 256, BufferUsage::none, MemoryLocation::device, "b");
    EXPECT_THROW(context().submit_and_wait([&](CommandList& cmd) {
        cmd.copy_buffer(a, b, 256);
        cmd.copy_buffer(a, b, 256);
        throw std::runtime_error("abandon");
    }),
                 std::runtime_error);
    bool hazard = false;
    for (const std::string& m : context().validation_messages()) {
        hazard = hazard || m.find("SYNC-HAZARD-WRITE-AFTER-WRITE") != std::string::npos;
    }
    EXPECT_TRUE(hazard) << context().validation_log().summary();
    context().validation_log().clear();
    // With the barrier it is clean.
    context().submit_and_wait([&](CommandList& cmd) {
        cmd.copy_buffer(a, b, 256);
        cmd.barrier();
        cmd.copy_buffer(a, b, 256);
    });
}

}  // namespace
}  // namespace mvpl::gpu
