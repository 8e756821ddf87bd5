#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs, only those missing.
# apt's output goes to a log (shown only if the installation fails).
set -euo pipefail
# Extra packages can be named as arguments (the tests add clang for libFuzzer).
# The library needs CGAL (with GMP and MPFR) and Boost; Eigen only for the
# Poisson size field; oneTBB only for meshing on several threads;
# Boost.Program_options and nlohmann-json only for the
# command-line tool.
packages=(libcgal-dev libboost-dev libboost-program-options-dev libgmp-dev libmpfr-dev libeigen3-dev
          nlohmann-json3-dev libtbb-dev "$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO=sudo
  log=$(mktemp /tmp/afm-apt.XXXXXX.log)
  if ! { $SUDO apt-get update -qq && \
         DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"; } \
       > "$log" 2>&1; then
    echo "apt-get failed; its last lines (whole log: $log):" >&2
    tail -n 20 "$log" >&2
    exit 1
  fi
  rm -f "$log"
fi
