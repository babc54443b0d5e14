#!/usr/bin/env bash
# Installs the Debian 12 packages learnid needs, only those that are missing.
# Sourced by scripts/run and scripts/test; needs root (or sudo) when something is missing.
set -euo pipefail

# Complete for a bare Debian 12 (debootstrap --variant=minbase), checked by CI's clean-room
# stage (.ci/run). Debian's qt6-charts-dev does not pull in the Qt6OpenGL CMake package that
# Qt6Charts' config asks for (libqt6opengl6-dev); CPack's DEB generator runs `file`.
LEARNID_PACKAGES=(
    build-essential cmake ninja-build pkg-config
    qt6-base-dev qt6-charts-dev libqt6opengl6-dev qt6-serialbus-dev qt6-tools-dev
    qt6-l10n-tools qt6-tools-dev-tools qt6-qpa-plugins libgl-dev libeigen3-dev
    xvfb xauth qt6-svg-dev
    dpkg-dev file  # tst_package: dpkg-shlibdeps, and CPack's DEB generator runs `file`
    clang libclang-rt-14-dev  # scripts/fuzz: libFuzzer and the sanitizer runtimes of clang
    clang-format  # scripts/format --check (CI)
    liburdfdom-dev  # URDF robots (core/model/UrdfChain)
    libassimp-dev  # URDF mesh files' bounding boxes (core/model/MeshBounds)
    zlib1g-dev  # Debian 12's assimp CMake targets link libz.so but libassimp-dev does not pull it in
    liborocos-kdl-dev  # tests only: Orocos KDL, the dynamics oracle of tst_chaindynamics
    can-utils  # scripts/test-socketcan: cansend, candump, canplayer inside the VM (CI)
    libsocketcan2  # Qt's socketcan plugin loads it: bus state and bitrate of a real controller
)

learnid_install_deps() {
    local missing=()
    for p in "${LEARNID_PACKAGES[@]}"; do
        if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
            missing+=("$p")
        fi
    done
    if [ ${#missing[@]} -eq 0 ]; then
        return 0
    fi
    echo "learnid: installing missing Debian packages: ${missing[*]}" >&2
    local sudo=""
    if [ "$(id -u)" -ne 0 ]; then
        if command -v sudo >/dev/null 2>&1; then
            sudo="sudo"
        else
            echo "learnid: run as root (or install sudo) to install: ${missing[*]}" >&2
            return 1
        fi
    fi
    $sudo apt-get update -q
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# Configures and builds into $1 (default: build) with extra CMake arguments after it; only the
# targets in LEARNID_BUILD_TARGETS (and what they need) when it is set.
learnid_build() {
    local dir="${1:-build}"
    shift || true
    local launcher=()
    if command -v ccache >/dev/null 2>&1; then
        # Optional: rebuilds (and other clones of the repository) reuse compiled objects.
        export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
        launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    fi
    cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" "$@"
    local targets=()
    if [ -n "${LEARNID_BUILD_TARGETS:-}" ]; then
        read -r -a targets <<<"$LEARNID_BUILD_TARGETS"
        targets=(--target "${targets[@]}")
    fi
    cmake --build "$dir" -j "$(nproc)" "${targets[@]}"
}
