#include "tests/gpu/gpu_test.h"

#if defined(__SANITIZE_ADDRESS__)  // GCC
#define MVPL_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)  // clang
#define MVPL_ADDRESS_SANITIZER 1
#endif
#endif

#if defined(MVPL_ADDRESS_SANITIZER)
// MVPL_SANITIZE builds: lavapipe's LLVM JIT leaks blocks that point at each other (reported as
// "indirect" leaks only), allocated in libraries that are unloaded at vkDestroyInstance, so
// LeakSanitizer can neither symbolise nor suppress them by name. Leak checking is off for this
// binary; AddressSanitizer's other checks stay on, and leaked Vulkan objects are reported by the
// validation layer's object tracker at context destruction (TearDownTestSuite).
extern "C" const char* __asan_default_options() {
    return "detect_leaks=0";
}
#endif

namespace mvpl::gpu::testing {

std::shared_ptr<ValidationLog> GpuTest::s_log;
std::unique_ptr<Context> GpuTest::s_context;
std::string GpuTest::s_error;

ContextOptions validated_options(std::shared_ptr<ValidationLog> log) {
    ContextOptions options;
    options.validation = true;
    options.validation_log = std::move(log);
    return options;
}

void GpuTest::SetUpTestSuite() {
    s_log = std::make_shared<ValidationLog>();
    s_error.clear();
    try {
        s_context = std::make_unique<Context>(validated_options(s_log));
    } catch (const std::exception& e) {
        // Reported by SetUp of every test, so that each one fails with the reason.
        s_error = e.what();
    }
}

void GpuTest::TearDownTestSuite() {
    s_context.reset();
    if (s_log) {
        EXPECT_EQ(s_log->count(), 0u) << "validation messages while the context was destroyed:\n"
                                      << s_log->summary();
    }
    s_log.reset();
}

void GpuTest::SetUp() {
    // Messages from creating the context count against the first test, so nothing is lost.
    ASSERT_TRUE(s_context) << "no validated Vulkan context: " << s_error;
}

void GpuTest::TearDown() {
    if (!s_log) return;
    EXPECT_EQ(s_log->count(), 0u) << "validation messages:\n" << s_log->summary();
    s_log->clear();  // one failure per finding, not one per later test
}

}  // namespace mvpl::gpu::testing
