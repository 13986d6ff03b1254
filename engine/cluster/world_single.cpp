// world() of a build without MPI (MVPL_MPI=OFF): always the one process.
#include "engine/cluster/cluster.h"

namespace mvpl::cluster {

Cluster& world() {
    return single_process();
}

bool mpi_built() {
    return false;
}

World::World(int*, char***) {}

World::~World() = default;

}  // namespace mvpl::cluster
