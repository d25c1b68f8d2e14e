#!/usr/bin/env bash
# Installs the Debian packages hpcontact needs, if any is missing (apt-get; root or sudo).
#   install-deps.sh         what the build, `make run` and `make test` need (BLIS, serial, as the
#                           BLAS under CHOLMOD's factorisation: 6 times the reference BLAS's speed at
#                           p = 15; one thread, so results do not depend on the thread count and a
#                           study's runs do not oversubscribe the cores; not OpenBLAS, 20 % faster,
#                           which loops for ever when its 128 MB buffer cannot be mapped under an
#                           address-space limit; Slurm's daemons and
#                           client for the test of `hpcontact study --executor slurm`, which
#                           starts its own private cluster: the packages' services stay unused;
#                           Chromium, which the test of report.html renders it with, headless)
#   install-deps.sh fuzz    and clang's libFuzzer for `make fuzz`
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config
  libeigen3-dev libsuitesparse-dev libblis4-serial libyaml-cpp-dev libcli11-dev libmuparser-dev
  nlohmann-json3-dev libgtest-dev libbenchmark-dev
  python3 python3-dev python3-numpy python3-matplotlib python3-pytest python3-yaml pybind11-dev
  python3-meshio
  gmsh
  slurmctld slurmd slurm-client
  chromium
)

if [ "${1:-}" = fuzz ]; then
  packages+=(clang libclang-rt-14-dev libomp-dev)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
