// The failures of a cluster run (mpirun): a process that failed or stopped, an MPI call that did
// not succeed. rt prints them on rank 0 and exits with status 5 (docs/distributed.md).
#pragma once

#include "rt/core/error.h"

namespace rt::cluster {

class ClusterError : public Error {
public:
    using Error::Error;
};

}  // namespace rt::cluster
