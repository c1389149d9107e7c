#!/usr/bin/env bash
# QGIS 3.40 LTR (Debian 13 "trixie": Python 3.13, numpy 2.2, GDAL 3.10) in a root made with
# debootstrap from Debian's own archive, to run this checkout's tests there.
#
#   scripts/qgis340_root.sh build           # create or update the root (idempotent, ~7 min)
#   scripts/qgis340_root.sh run CMD ARGS…   # run CMD inside it, in this checkout
#   scripts/qgis340_root.sh test [ARGS…]    # build, then `make test PYTEST_ARGS="ARGS…"` inside
#   scripts/qgis340_root.sh shell           # an interactive shell inside it
#
# The root lives in $QGIS340_ROOT (default /var/tmp/geomatics-qgis340-root) and is reused.
# Each run happens in a private mount namespace (unshare): /proc, /sys and /dev are mounted,
# the checkout is bind-mounted at its own path and ../shared beside it (read-only), so the
# data tests find ../shared/data as they do outside; the mounts vanish with the run, and
# runs of different checkouts can share one root. The root's venv is its own
# (/opt/venv/<checkout path>, made by the Makefile with VENV=…), never the checkout's
# .venv. pip inside reaches the package index with this machine's /etc/pip.conf and the CA
# files that SSL_CERT_FILE / PIP_CERT / REQUESTS_CA_BUNDLE name, copied in.
set -euo pipefail

ROOT=${QGIS340_ROOT:-/var/tmp/geomatics-qgis340-root}
SUITE=trixie
CHECKOUT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd -P)
SHARED=$(dirname "$CHECKOUT")/shared
VENV=/opt/venv$CHECKOUT
PACKAGES="qgis python3-qgis qgis-providers python3-gdal gdal-bin python3-scipy python3-venv \
python3-pip qttools5-dev-tools pyqt5-dev-tools chromium xvfb xauth make git ca-certificates \
locales-all"
CA_VARS="SSL_CERT_FILE PIP_CERT REQUESTS_CA_BUNDLE CURL_CA_BUNDLE"

log() { printf '[qgis340_root] %s\n' "$*" >&2; }

# The Debian archive this machine uses (deb822 sources first, then sources.list).
mirror() {
    if [ -n "${QGIS340_MIRROR:-}" ]; then echo "$QGIS340_MIRROR"; return; fi
    local uri=""
    if [ -r /etc/apt/sources.list.d/debian.sources ]; then
        uri=$(awk '/^URIs:/ { for (i = 2; i <= NF; i++) if ($i !~ /security/) { print $i; exit } }' \
            /etc/apt/sources.list.d/debian.sources)
    fi
    if [ -z "$uri" ] && [ -r /etc/apt/sources.list ]; then
        uri=$(awk '/^deb / && $0 !~ /security/ { for (i = 2; i <= NF; i++) if ($i ~ /:\/\//) { print $i; exit } }' \
            /etc/apt/sources.list)
    fi
    echo "${uri:-http://deb.debian.org/debian}"
}

# Copy this machine's pip configuration and CA bundles into the root (same paths), so pip
# inside reaches the package index exactly as it does here. Re-done before every run:
# Debian's ca-certificates in the root would otherwise regenerate the bundle without them.
copy_host_config() {
    cp -f /etc/resolv.conf "$ROOT/etc/resolv.conf" 2>/dev/null || true
    if [ -r /etc/pip.conf ]; then cp -f /etc/pip.conf "$ROOT/etc/pip.conf"; fi
    local var file
    for var in $CA_VARS; do
        file=${!var:-}
        if [ -n "$file" ] && [ -f "$file" ]; then
            mkdir -p "$ROOT$(dirname "$file")"
            cmp -s "$file" "$ROOT$file" 2>/dev/null || cp -fL "$file" "$ROOT$file"
        fi
    done
    # a CA file named in pip.conf (cert = …)
    if [ -r /etc/pip.conf ]; then
        file=$(awk -F'=' '/^[[:space:]]*cert[[:space:]]*=/ { gsub(/[[:space:]]/, "", $2); print $2; exit }' /etc/pip.conf)
        if [ -n "$file" ] && [ -f "$file" ]; then
            mkdir -p "$ROOT$(dirname "$file")"
            cmp -s "$file" "$ROOT$file" 2>/dev/null || cp -fL "$file" "$ROOT$file"
        fi
    fi
}

# Run "$@" chrooted in the root inside a private mount namespace.
in_root() {
    local workdir=$1; shift
    local envs=(HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin
        LANG=C.UTF-8 LC_ALL=C.UTF-8 TERM="${TERM:-dumb}" DEBIAN_FRONTEND=noninteractive
        QGIS340_VENV="$VENV")
    local var
    for var in $CA_VARS SSL_CERT_DIR PIP_INDEX_URL PIP_EXTRA_INDEX_URL PIP_TRUSTED_HOST \
            PIP_DEFAULT_TIMEOUT PIP_DISABLE_PIP_VERSION_CHECK http_proxy https_proxy no_proxy \
            HTTP_PROXY HTTPS_PROXY NO_PROXY CI GEOMATICS_ISPRS_DIR; do
        if [ -n "${!var:-}" ]; then envs+=("$var=${!var}"); fi
    done
    local shared_ro="" gitdir=""
    if [ -d "$SHARED" ]; then shared_ro=$SHARED; fi
    # a git worktree keeps its repository elsewhere (.git is a file): mount that too
    # (read-only), so `git ls-files` works inside (package and i18n tests)
    if [ -f "$CHECKOUT/.git" ]; then
        gitdir=$(git -C "$CHECKOUT" rev-parse --path-format=absolute --git-common-dir 2>/dev/null || true)
        case "$gitdir" in "$CHECKOUT"/*|"") gitdir="" ;; esac
    fi
    unshare --mount --propagation private -- bash -eu -c '
        root=$1 checkout=$2 shared=$3 workdir=$4 gitdir=$5; shift 5
        mount -t proc proc "$root/proc"
        mount --rbind /sys "$root/sys"
        mount --rbind /dev "$root/dev"
        mkdir -p "$root/dev/shm" 2>/dev/null || true
        mount -t tmpfs -o mode=1777 tmpfs "$root/dev/shm"
        mkdir -p "$root$checkout"
        mount --bind "$checkout" "$root$checkout"
        if [ -n "$shared" ]; then
            mkdir -p "$root$shared"
            mount --bind "$shared" "$root$shared"
            mount -o remount,bind,ro "$root$shared"
        fi
        if [ -n "$gitdir" ]; then
            mkdir -p "$root$gitdir"
            mount --bind "$gitdir" "$root$gitdir"
            mount -o remount,bind,ro "$root$gitdir"
        fi
        envs=()
        while [ "$1" != "--" ]; do envs+=("$1"); shift; done
        shift
        exec chroot "$root" /usr/bin/env -i "${envs[@]}" \
            /bin/bash -c "cd \"\$0\" && exec \"\$@\"" "$workdir" "$@"
    ' _ "$ROOT" "$CHECKOUT" "$shared_ro" "$workdir" "$gitdir" "${envs[@]}" -- "$@"
}

build() {
    local t0=$SECONDS
    mkdir -p "$(dirname "$ROOT")"
    exec 9>"$ROOT.lock"
    flock 9
    if [ ! -f "$ROOT/.debootstrap-done" ]; then
        if ! command -v debootstrap >/dev/null 2>&1; then
            log "installing debootstrap"
            apt-get update -qq && apt-get install -y -qq --no-install-recommends debootstrap >/dev/null
        fi
        rm -rf "$ROOT"
        log "debootstrap $SUITE from $(mirror) into $ROOT"
        debootstrap --variant=minbase "$SUITE" "$ROOT" "$(mirror)" >"$ROOT.debootstrap.log" 2>&1 \
            || { tail -n 30 "$ROOT.debootstrap.log" >&2; exit 1; }
        touch "$ROOT/.debootstrap-done"
    fi
    copy_host_config
    local want
    want=$(echo "$PACKAGES" | tr -s ' ' '\n' | sort | tr '\n' ' ')
    if [ "$(cat "$ROOT/.packages-done" 2>/dev/null)" != "$want" ]; then
        log "apt-get install (QGIS 3.40 and tools) in the root"
        printf 'Types: deb\nURIs: %s\nSuites: %s %s-updates\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
            "$(mirror)" "$SUITE" "$SUITE" > "$ROOT/etc/apt/sources.list.d/debian.sources"
        rm -f "$ROOT/etc/apt/sources.list"
        # no daemons inside the root
        printf '#!/bin/sh\nexit 101\n' > "$ROOT/usr/sbin/policy-rc.d"
        chmod +x "$ROOT/usr/sbin/policy-rc.d"
        # shellcheck disable=SC2086
        in_root / bash -c "apt-get update -qq && apt-get install -y -qq --no-install-recommends $PACKAGES" \
            >"$ROOT.apt.log" 2>&1 || { tail -n 30 "$ROOT.apt.log" >&2; exit 1; }
        in_root / apt-get clean
        echo "$want" > "$ROOT/.packages-done"
        copy_host_config
    fi
    exec 9>&-
    log "root ready in $((SECONDS - t0)) s: $(in_root / bash -c 'qgis_process.bin --version 2>/dev/null | grep -m1 QGIS; python3 --version' | tr '\n' ' ')"
}

case "${1:-}" in
    build)
        build ;;
    run)
        shift; [ -f "$ROOT/.packages-done" ] || build
        copy_host_config
        in_root "$CHECKOUT" "$@" ;;
    shell)
        [ -f "$ROOT/.packages-done" ] || build
        copy_host_config
        in_root "$CHECKOUT" bash ;;
    test)
        shift; build
        in_root "$CHECKOUT" make VENV="$VENV" test PYTEST_ARGS="$*" ;;
    *)
        sed -n '2,17p' "$0" >&2; exit 2 ;;
esac
