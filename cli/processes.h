// The processes this candela is one of (an MPI job's ranks, study/mpi_distribution.h): set once
// by main.cpp, read by the commands that trace.
#pragma once

#include "base/distribution.h"

namespace candela::cli {

// localDistribution() until main sets the MPI job's.
const Distribution& processes();
void setProcesses(const Distribution& d);

// Whether this process prints results and progress (rank 0, or the only process).
inline bool printsResults() { return processes().rank() == 0 || processes().partial(); }

}  // namespace candela::cli
