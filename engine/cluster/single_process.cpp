#include "engine/cluster/cluster.h"

#include <cstdlib>

#include "engine/core/error.h"

namespace mvpl::cluster {

namespace {

class SingleProcess final : public Cluster {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    void sum_all(std::span<double>) override {}
    void sum_all(std::span<uint64_t>) override {}
    void sum_to_root(std::span<float>) override {}
    std::vector<double> gather_all(std::span<const double> values) override {
        return {values.begin(), values.end()};
    }
    void agree(std::exception_ptr error) override {
        if (error) std::rethrow_exception(error);
    }
    [[noreturn]] void abort(int code) override { std::exit(code); }
};

}  // namespace

int exit_code_of(std::exception_ptr error) {
    try {
        std::rethrow_exception(error);
    } catch (const RankFailure& e) {
        return e.code();
    } catch (const InputError&) {
        return 2;
    } catch (const UsageError&) {
        return 2;
    } catch (...) {
        return 1;
    }
}

std::string message_of(std::exception_ptr error) {
    try {
        std::rethrow_exception(error);
    } catch (const std::exception& e) {
        return e.what();
    } catch (...) {
        return "unknown exception";
    }
}

Cluster& single_process() {
    static SingleProcess instance;
    return instance;
}

}  // namespace mvpl::cluster
