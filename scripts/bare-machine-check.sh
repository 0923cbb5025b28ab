#!/usr/bin/env bash
# The README's two commands on a bare Debian 12: makes a bookworm root with
# debootstrap (minbase, plus make, g++ and git: no Python), makes a clean
# `git clone` of this repository's HEAD in it, and runs `make run`, then
# `make test`, there as root in a chroot. An install step missing from the
# Makefile or scripts/install-deps.sh fails here, not on a user's machine.
# Nothing is cached between runs: the root is made from Debian's packages each
# time and removed at the end. Exits non-zero when a step fails.
#
# Needs root, debootstrap and network access to a Debian mirror. Environment:
#   BARE_MIRROR  the Debian mirror (default: the host's apt sources' bookworm URI)
#   BARE_DIR     the directory to make the root in (default: a new one under
#                ${TMPDIR:-/var/tmp}); it must not exist or be empty
#   BARE_KEEP=1  keep the root after the run (to look into a failure)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
suite=bookworm
started=$(date +%s)

say() { printf '[bare-machine %s] %s\n' "$(date -u +%H:%M:%S)" "$*"; }
die() { say "FAILED: $*" >&2; exit 1; }
seconds_text() { printf '%dm%02ds' $(($1 / 60)) $(($1 % 60)); }

[ "$(id -u)" -eq 0 ] || die "needs root (debootstrap, mount, chroot)"
command -v debootstrap >/dev/null || die "needs debootstrap (apt-get install debootstrap)"

# The first URI apt uses for the suite itself (not -updates or -security), from
# the one-line format (sources.list, *.list) and the deb822 one (*.sources).
host_mirror() {
    local files=() f
    for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources; do
        [ -f "$f" ] && files+=("$f")
    done
    [ ${#files[@]} -gt 0 ] || return 0
    awk -v suite="$suite" '
        FNR == 1 { types = ""; uris = ""; suites = "" }
        FILENAME !~ /\.sources$/ {
            if ($1 != "deb") next
            i = 2
            if ($i ~ /^\[/) { while ($i !~ /\]$/) i++; i++ }
            if ($(i + 1) == suite) { print $i; exit }
            next
        }
        /^[ \t]*$/ { types = ""; uris = ""; suites = ""; next }
        /^Types:/  { types = " " $0 " " }
        /^URIs:/   { uris = $2 }
        /^Suites:/ { suites = " " $0 " " }
        types ~ / deb / && index(suites, " " suite " ") && uris != "" { print uris; exit }
    ' "${files[@]}"
}
mirror=${BARE_MIRROR:-$(host_mirror)}
[ -n "$mirror" ] || die "no $suite mirror in /etc/apt/sources.list*: set BARE_MIRROR"

if [ -n "${BARE_DIR:-}" ]; then
    root=$BARE_DIR
    mkdir -p "$root"
    [ -z "$(ls -A "$root")" ] || die "BARE_DIR=$root is not empty"
else
    root=$(mktemp -d "${TMPDIR:-/var/tmp}/ellvor-bare.XXXXXX")
fi
root=$(cd "$root" && pwd)

# The mount points under the root, deepest first.
mounts_under_root() {
    awk -v r="$root" '$5 == r || index($5, r "/") == 1 { print $5 }' /proc/self/mountinfo | sort -r
}

declare -a phase_names=() phase_seconds=()
phase_pid=""
# Runs at every exit (failure, Ctrl-C, a TERM to this shell alone): stops the
# running phase and what still runs in the root (only processes started by
# this script run there), unmounts, removes.
cleanup() {
    local status=$? pid m pass
    trap - EXIT INT TERM
    for pass in 1 2; do
        for pid in $(ls /proc | grep -E '^[0-9]+$'); do
            [ "$(readlink "/proc/$pid/root" 2>/dev/null)" = "$root" ] && kill -KILL "$pid" 2>/dev/null || true
        done
        [ -z "$phase_pid" ] || kill -KILL "$phase_pid" 2>/dev/null || true
    done
    [ -z "$phase_pid" ] || wait "$phase_pid" 2>/dev/null || true
    rm -f "$root.debootstrap.log"
    for m in $(mounts_under_root); do
        umount "$m" 2>/dev/null || umount --lazy "$m" || say "could not unmount $m"
    done
    if [ -n "$(mounts_under_root)" ]; then
        say "still mounted under $root, not removed:"; mounts_under_root
        status=1
    elif [ "${BARE_KEEP:-0}" = 1 ]; then
        say "root kept in $root (BARE_KEEP=1)"
    else
        # --one-file-system: never into a mount, even one that appeared since.
        rm -rf --one-file-system "$root"
    fi
    say "$([ "$status" -eq 0 ] && echo passed || echo FAILED) (exit status $status); phases:"
    for i in "${!phase_names[@]}"; do
        printf '  %-50s %s\n' "${phase_names[$i]}" "$(seconds_text "${phase_seconds[$i]}")"
    done
    say "total $(seconds_text $(($(date +%s) - started)))"
    exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# phase NAME COMMAND...: runs COMMAND, prints and records its elapsed time.
# In the background, so that a signal's trap runs at once, not when it ends.
phase() {
    local name=$1 t0 status=0
    shift
    say "== $name"
    t0=$(date +%s)
    "$@" &
    phase_pid=$!
    wait "$phase_pid" || status=$?
    phase_pid=""
    phase_names+=("$name")
    phase_seconds+=($(($(date +%s) - t0)))
    say "== $name: $(seconds_text "${phase_seconds[-1]}")$([ $status -eq 0 ] || echo ", FAILED (exit $status)")"
    return "$status"
}

commit=$(git -C "$repo" rev-parse HEAD)
say "commit $commit of $repo; root $root; mirror $mirror"
[ -z "$(git -C "$repo" status --porcelain --untracked-files=no)" ] ||
    say "note: uncommitted changes in $repo are not tested (the clone is of HEAD)"

# debootstrap's log is long: only its end is shown, on failure.
make_root() {
    local log=$root.debootstrap.log status=0
    debootstrap --variant=minbase --include=make,g++,git "$suite" "$root" "$mirror" >"$log" 2>&1 || status=$?
    [ $status -eq 0 ] || tail -n 30 "$log"
    rm -f "$log"
    return "$status"
}
phase "debootstrap $suite (minbase + make, g++, git)" make_root
if compgen -G "$root/usr/bin/python*" >/dev/null; then
    die "the root has Python before the README's commands: $(ls "$root"/usr/bin/python*)"
fi

# /dev bound without its submounts, made a slave so that nothing mounted below
# it reaches the host's /dev; its own pts and shm.
mount -t proc proc "$root/proc"
mount --bind /dev "$root/dev"
mount --make-rslave "$root/dev"
mount --bind /dev/pts "$root/dev/pts"
mount -t tmpfs -o mode=1777,nosuid,nodev shm "$root/dev/shm"

phase "git clone (HEAD, from $repo)" \
    bash -c 'git clone --quiet --no-hardlinks "$1" "$2" &&
             git -C "$2" -c advice.detachedHead=false checkout --quiet --detach "$3"' \
    _ "$repo" "$root/root/ellvor" "$commit"

in_root() {
    chroot "$root" /usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb \
        PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
        /bin/bash -c "cd /root/ellvor && $1"
}
phase "make run" in_root "make run"
phase "make test" in_root "make test"

