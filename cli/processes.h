// The processes this candela is one of (an MPI job's ranks, study/distributed/mpi_distribution.h): set once
// by main.cpp, read by the commands that trace.
#pragma once

#include "base/distribution.h"

namespace candela::cli {

// localDistribution() until main sets the MPI job's.
const Distribution& processes();
void setProcesses(const Distribution& d);

// Whether a process of `d` prints results and progress: rank 0 (or the only process), or a shard
// (each prints its own part's line).
inline bool printsResults(const Distribution& d = processes()) { return d.rank() == 0 || d.partial(); }

}  // namespace candela::cli
