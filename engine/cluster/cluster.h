#pragma once
// The ranks of one job: a render spread over processes started by `mpirun` (issue 17), or one
// process alone. Only the operations mvpl needs, so that the sampler and the renderer's callers
// stay free of mpi.h: the MPI implementation (mpi_cluster.cpp) exists only when the build found
// MPI (MVPL_MPI), the one-process implementation always.
//
// Failures: a rank that throws while the others wait in a collective call would hang the job.
// So every collective call is preceded by an agreement point (agree(), or together() below) at
// which each rank says whether it failed; if any did, every rank throws the same RankFailure
// (the message and exit code of the lowest failing rank), so all exit alike and rank 0 alone
// prints the line. On one process agree() simply rethrows the error. The agreement points are
// all the same collective call, so a rank that fails skips to the next one it meets and the others
// meet it there, whatever the code between; what may not throw is the code between an agreement
// point and the collective call it guards. A RankFailure (agreed already) passes every later
// agreement point without a collective call, as it passes on every rank.
#include <cstdint>
#include <exception>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace mvpl::cluster {

// Thrown on every rank when one rank failed: the failing rank's one-line message and the exit
// code its error maps to (2 bad input or usage, 1 internal).
class RankFailure : public std::runtime_error {
public:
    RankFailure(const std::string& message, int code, int rank)
        : std::runtime_error(message), m_code(code), m_rank(rank) {}
    int code() const { return m_code; }
    int rank() const { return m_rank; }

private:
    int m_code;
    int m_rank;
};

// The exit code an error maps to: 2 for InputError and UsageError (engine/core/error.h), 1 else.
int exit_code_of(std::exception_ptr error);
// Its message, as main prints it after "mvpl: error: " (or "mvpl: internal error: ").
std::string message_of(std::exception_ptr error);

class Cluster {
public:
    virtual ~Cluster() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    bool root() const { return rank() == 0; }

    // Element-wise sums over the ranks, the result on every rank (MPI_Allreduce).
    virtual void sum_all(std::span<double> values) = 0;
    virtual void sum_all(std::span<uint64_t> values) = 0;
    // Element-wise sum over the ranks into rank 0's values (MPI_Reduce); the others' values are
    // left as they were.
    virtual void sum_to_root(std::span<float> values) = 0;
    // Every rank's values, concatenated in rank order, on every rank (MPI_Allgatherv).
    virtual std::vector<double> gather_all(std::span<const double> values) = 0;
    // The agreement point: `error` is this rank's failure since the last one (null: none).
    // Returns on every rank when none failed, else throws on every rank (see above).
    virtual void agree(std::exception_ptr error) = 0;
    // The last resort when ranks can no longer agree (an error outside the agreement points):
    // ends every rank with `code` (MPI_Abort).
    [[noreturn]] virtual void abort(int code) = 0;
};

// One process, rank 0 of 1: every collective leaves the values as they are.
Cluster& single_process();

// The cluster of this process: set up by a World in main, else single_process().
Cluster& world();

// MPI_Init … MPI_Finalize for main when the process was started by mpirun (Open MPI's
// OMPI_COMM_WORLD_SIZE in the environment) and the build has MPI; otherwise nothing, and
// world() stays single_process(), so a plain `mvpl` never initialises MPI.
class World {
public:
    World(int* argc, char*** argv);
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

private:
    std::unique_ptr<Cluster> m_cluster;
};

// Whether this build can run across ranks (mvpl info, tests).
bool mpi_built();

// Runs `f` on this rank, then meets the others at an agreement point: returns on every rank, or
// throws the same RankFailure on every rank (on one process: f's own exception).
template <class F>
void together(Cluster& cluster, F&& f) {
    std::exception_ptr error;
    try {
        f();
    } catch (...) {
        error = std::current_exception();
    }
    cluster.agree(error);
}

// This rank's share [first, last) of `count` items split into contiguous near-equal parts in rank
// order.
struct Share {
    uint64_t first = 0;
    uint64_t last = 0;
};
inline Share share_of(uint64_t count, int rank, int size) {
    auto bound = [&](int r) {
        return uint64_t((unsigned __int128)(count) * unsigned(r) / unsigned(size));
    };
    return {bound(rank), bound(rank + 1)};
}

}  // namespace mvpl::cluster
