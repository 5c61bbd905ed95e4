#include "cli/processes.h"

namespace candela::cli {

namespace {
const Distribution* current = nullptr;
}  // namespace

const Distribution& processes() { return current ? *current : localDistribution(); }
void setProcesses(const Distribution& d) { current = &d; }

}  // namespace candela::cli
