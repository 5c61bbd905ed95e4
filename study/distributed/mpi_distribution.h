// The ranks of an MPI job as a Distribution (base/distribution.h): `mpirun -n N candela run ...`
// splits the items of every fill over the ranks, balanced dynamically (a rank takes the next
// chunk of items when it is done with its last, from a counter on rank 0 that every rank
// increments by a one-sided atomic fetch-and-add), and every rank receives every item. Which
// rank computed an item changes nothing in its bytes (each item has its own random stream), so
// the result is the one-process result for any N (docs/distributed.md).
//
// Built when CMake finds MPI (CANDELA_HAVE_MPI); without it, mpiSession() is a single process.
#pragma once

#include "base/distribution.h"

#include <memory>

namespace candela {

// MPI for the life of the program: initialised when the process was started by an MPI launcher
// (mpirun, srun), finalised by the destructor. Holds the world's Distribution.
class MpiSession {
 public:
  // Starts MPI only when the environment shows an MPI launcher (Open MPI's, PMI's or PMIx's
  // variables): a plain `candela run` never loads MPI's run-time.
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  // The job's ranks, or localDistribution() for a plain process.
  const Distribution& distribution() const;
  bool active() const { return impl_ != nullptr; }
  // Ends every rank of the job with `exitCode` (a failure on one rank that the others cannot
  // know of: they would wait for it forever). Returns only without MPI.
  void abort(int exitCode) const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

// Whether this build can run under MPI.
bool mpiAvailable();

}  // namespace candela
