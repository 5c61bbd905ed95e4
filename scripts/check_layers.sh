#!/usr/bin/env bash
# The dependency rule of docs/architecture.md, checked on the sources: each layer includes only
# the layers above it. Prints every offending include and exits 1 when there is one.
#
#   scripts/check_layers.sh [SOURCE_DIR]
set -uo pipefail
root="${1:-$(cd "$(dirname "$0")/.." && pwd)}"
cd "$root"
status=0
# layer:folders it must not include
rules=(
  "base:photometry engine metrics reports study validation cli"
  "photometry:engine metrics reports study validation cli"
  "engine:metrics reports study validation cli"
  "metrics:photometry engine reports study validation cli"
  "reports:photometry engine study validation cli"
  "study:validation cli"
  "validation:cli"
)
for rule in "${rules[@]}"; do
  layer="${rule%%:*}"
  for banned in ${rule#*:}; do
    if hits=$(grep -rn --include='*.h' --include='*.cpp' "#include \"$banned/" "$layer" 2>/dev/null); then
      echo "$layer/ must not include $banned/:"
      echo "$hits"
      status=1
    fi
  done
done
# base/ uses the standard library (and POSIX), GLM and TBB only.
if hits=$(grep -rhn --include='*.h' --include='*.cpp' '#include <' base | grep -v -E '#include <(glm/|tbb/|sys/|unistd.h>|fcntl.h>|[a-z_]+>)'); then
  echo "base/ includes more than the standard library, GLM and TBB:"
  echo "$hits"
  status=1
fi
[ $status = 0 ] && echo "layers: every include points upwards"
exit $status
