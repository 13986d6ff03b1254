#pragma once
// One validated Context per test suite (creating one with the layer costs ~0.1–0.5 s on
// lavapipe): every test asserts that the layer said nothing during it, and the suite asserts
// that nothing was reported when the context went away (leaked objects).
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "engine/gpu/context.h"
#include "engine/gpu/validation.h"

namespace mvpl::gpu::testing {

class GpuTest : public ::testing::Test {
protected:
    static void SetUpTestSuite();
    static void TearDownTestSuite();
    void SetUp() override;
    void TearDown() override;

    static Context& context() { return *s_context; }

private:
    static std::shared_ptr<ValidationLog> s_log;
    static std::unique_ptr<Context> s_context;
    static std::string s_error;
};

// A context for tests that need their own (environment variations, device enumeration).
ContextOptions validated_options(std::shared_ptr<ValidationLog> log);

}  // namespace mvpl::gpu::testing
