// The cluster over Open MPI's MPI_COMM_WORLD (built only with MVPL_MPI). mpi.h stays in this file.
#include <mpi.h>

#include <climits>
#include <cstdlib>
#include <stdexcept>

#include "engine/cluster/cluster.h"

namespace mvpl::cluster {

namespace {

Cluster* g_world = nullptr;

int checked_count(size_t n) {
    if (n > size_t(INT_MAX)) throw std::length_error("cluster: more than 2^31 values at once");
    return int(n);
}

class MpiCluster final : public Cluster {
public:
    MpiCluster() {
        MPI_Comm_rank(MPI_COMM_WORLD, &m_rank);
        MPI_Comm_size(MPI_COMM_WORLD, &m_size);
    }
    int rank() const override { return m_rank; }
    int size() const override { return m_size; }

    void sum_all(std::span<double> v) override {
        MPI_Allreduce(MPI_IN_PLACE, v.data(), checked_count(v.size()), MPI_DOUBLE, MPI_SUM,
                      MPI_COMM_WORLD);
    }
    void sum_all(std::span<uint64_t> v) override {
        MPI_Allreduce(MPI_IN_PLACE, v.data(), checked_count(v.size()), MPI_UINT64_T, MPI_SUM,
                      MPI_COMM_WORLD);
    }
    void sum_to_root(std::span<float> v) override {
        const int n = checked_count(v.size());
        if (m_rank == 0) {
            MPI_Reduce(MPI_IN_PLACE, v.data(), n, MPI_FLOAT, MPI_SUM, 0, MPI_COMM_WORLD);
        } else {
            MPI_Reduce(v.data(), nullptr, n, MPI_FLOAT, MPI_SUM, 0, MPI_COMM_WORLD);
        }
    }
    std::vector<double> gather_all(std::span<const double> v) override {
        int mine = checked_count(v.size());
        const auto n = size_t(m_size);
        std::vector<int> counts(n, 0), offsets(n, 0);
        MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
        size_t total = 0;
        for (int r = 0; r < m_size; ++r) {
            offsets[size_t(r)] = checked_count(total);
            total += size_t(counts[size_t(r)]);
        }
        std::vector<double> all(total);
        MPI_Allgatherv(v.data(), mine, MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
                       MPI_DOUBLE, MPI_COMM_WORLD);
        return all;
    }
    void agree(std::exception_ptr error) override {
        // A failure agreed on already (an inner agreement point) passes through: every rank
        // throws it, at whichever point it was, and none waits here for the others.
        if (error) {
            try {
                std::rethrow_exception(error);
            } catch (const RankFailure&) {
                throw;
            } catch (...) {
            }
        }
        // The lowest failing rank speaks for all: its exit code and message go to every rank.
        int failed = error ? m_rank : m_size;
        MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
        if (failed == m_size) return;
        std::string message;
        int header[2] = {1, 0};
        if (failed == m_rank) {
            message = message_of(error);
            header[0] = exit_code_of(error);
            header[1] = checked_count(message.size());
        }
        MPI_Bcast(header, 2, MPI_INT, failed, MPI_COMM_WORLD);
        message.resize(size_t(header[1]));
        MPI_Bcast(message.data(), header[1], MPI_CHAR, failed, MPI_COMM_WORLD);
        throw RankFailure(message, header[0], failed);
    }
    [[noreturn]] void abort(int code) override {
        MPI_Abort(MPI_COMM_WORLD, code);
        std::exit(code);  // MPI_Abort does not return; for the compiler
    }

private:
    int m_rank = 0;
    int m_size = 1;
};

// Open MPI's launcher (mpirun, or a PMIx server under a batch system) sets these.
bool started_by_mpirun() {
    return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMIX_RANK") != nullptr;
}

}  // namespace

Cluster& world() {
    return g_world ? *g_world : single_process();
}

bool mpi_built() {
    return true;
}

World::World(int* argc, char*** argv) {
    if (!started_by_mpirun()) return;
    // Only the main thread calls MPI (the compensation and tracing threads never do).
    int provided = 0;
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    m_cluster = std::make_unique<MpiCluster>();
    g_world = m_cluster.get();
}

World::~World() {
    if (!m_cluster) return;
    g_world = nullptr;
    m_cluster.reset();
    MPI_Finalize();
}

}  // namespace mvpl::cluster
