#!/usr/bin/env bash
# Usage: scripts/check-fresh-machine.sh [ROOT_DIR] [--commit REV] [--keep]
#
# Runs the README's two commands as a new user would, on a freshly installed, up-to-date Debian
# bookworm that has only g++, CMake, make, git and GoogleTest: the check that a green CI on a
# developer's machine cannot be (that machine has packages, and versions of them, that a fresh
# one lacks).  Needs root (debootstrap, chroot, mount) and Debian's mirrors.
#
#  1. debootstrap --variant=minbase bookworm into ROOT_DIR (default: /var/tmp/fas-fresh-machine,
#     emptied first), with g++, cmake, make, git, googletest and libgtest-dev; the package lists
#     of bookworm, bookworm-updates and bookworm-security, and `apt-get upgrade`: up to date;
#  2. clones the project (REV, default HEAD, of this clone) into ROOT_DIR/work/main, with this
#     clone's ../shared beside it (mounted read-only);
#  3. runs `CI=true bash .ci/run` there, then `scripts/run-main-job.sh` from a second fresh clone
#     (ROOT_DIR/work/job/main), and reports each one's time and exit status.
#
#   --keep     keeps ROOT_DIR afterwards (default: removed when both commands pass)
#
# Takes about 35 to 45 minutes on 2 cores (the cold CI run is most of it), so it is not part of
# .ci/run.  Run it whenever scripts/install-deps.sh, the top-level CMakeLists.txt, a writer or
# reader of VTK files, or a tool the tests use changes, and record its last result in
# benchmark/Flow_aligned_surfaces/RESULTS.md, "CI and fresh-machine times".  The logs stay in ROOT_DIR.log/.
# Exit status: 0 when both commands pass, 1 when one fails, 2 for a bad command line.
set -euo pipefail
source "$(dirname "$0")/lib/help.sh"
exit_if_help_asked "$@"
clone=$(cd "$(dirname "$0")/.." && pwd)

root=/var/tmp/fas-fresh-machine
rev=HEAD
keep=0
while [ $# -gt 0 ]; do
  case "$1" in
    --commit) rev=${2:?--commit needs a revision}; shift ;;
    --keep) keep=1 ;;
    -*) echo "usage: scripts/check-fresh-machine.sh [ROOT_DIR] [--commit REV] [--keep]" >&2; exit 2 ;;
    *) root=$1 ;;
  esac
  shift
done
if [ "$(id -u)" -ne 0 ]; then
  echo "check-fresh-machine: needs root (debootstrap, chroot and mount)" >&2
  exit 2
fi
shared=$(cd "$clone/.." && pwd)/shared
[ -d "$shared" ] || { echo "check-fresh-machine: no $shared beside the clone" >&2; exit 2; }
commit=$(git -C "$clone" rev-parse --verify "$rev^{commit}")
logs="$root.log"
mirror=http://deb.debian.org/debian

say() { echo "check-fresh-machine: $*"; }

# debootstrap itself, from Debian's packages, as install-deps.sh would: never removing anything.
if ! command -v debootstrap > /dev/null; then
  apt-get update -qq
  if apt-get install -s --no-install-recommends debootstrap | grep -q '^Remv'; then
    echo "check-fresh-machine: installing debootstrap would remove packages; install it yourself" >&2
    exit 1
  fi
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap
fi

mounted=()
unmount_all() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[i]}" 2> /dev/null || true; done
  mounted=()
}
# Whatever is still mounted below the root (a run that was killed leaves /proc, /dev and ../shared
# there): unmounted before anything below the root is removed, deepest first.
unmount_leftovers() {
  local point
  awk -v root="$root/" 'index($2, root) == 1 { print $2 }' /proc/mounts | sort -r |
    while read -r point; do umount -l "$point" 2> /dev/null || true; done
  if awk -v root="$root/" 'index($2, root) == 1 { found = 1 } END { exit !found }' /proc/mounts; then
    echo "check-fresh-machine: cannot unmount what is mounted below $root; remove it by hand" >&2
    exit 1
  fi
}
remove_root() { unmount_leftovers; rm -rf --one-file-system "$root"; }
trap unmount_all EXIT
bind() { mkdir -p "$2"; mount --bind "$1" "$2"; mounted+=("$2"); }

remove_root
rm -rf "$logs"
mkdir -p "$root" "$logs"
say "debootstrap bookworm into $root (log: $logs/debootstrap.log)"
start=$SECONDS
debootstrap --variant=minbase --include=g++,cmake,make,git,googletest,libgtest-dev,ca-certificates \
  bookworm "$root" "$mirror" > "$logs/debootstrap.log" 2>&1
cat > "$root/etc/apt/sources.list" <<EOF
deb $mirror bookworm main
deb $mirror bookworm-updates main
deb http://deb.debian.org/debian-security bookworm-security main
EOF
cp /etc/resolv.conf "$root/etc/resolv.conf"
bind /proc "$root/proc"
bind /sys "$root/sys"
bind /dev "$root/dev"
bind /dev/pts "$root/dev/pts"
mkdir -p "$root/dev/shm" && mount -t tmpfs tmpfs "$root/dev/shm" && mounted+=("$root/dev/shm")
in_root() { chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 "$@"; }
in_root bash -c 'apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get upgrade -y -qq' \
  >> "$logs/debootstrap.log" 2>&1
setup=$((SECONDS - start))
say "a fresh bookworm in ${setup} s: $(in_root dpkg-query -W -f='${Package} ${Version}' libexpat1)"

# The clones and ../shared beside them.
for dir in work job; do
  git clone -q --no-local "$clone" "$root/$dir/main"
  git -C "$root/$dir/main" checkout -q "$commit"
  bind "$shared" "$root/$dir/shared"
  mount -o remount,bind,ro "$root/$dir/shared"
done

run() { # NAME DIR COMMAND...: runs COMMAND in DIR inside the root; prints "status seconds"
  local name=$1 dir=$2 t=$SECONDS status=0
  shift 2
  in_root bash -c "cd $dir && $*" > "$logs/$name.log" 2>&1 || status=$?
  echo "$status $((SECONDS - t))"
}
say "CI=true bash .ci/run (log: $logs/ci.log)"
read -r ci_status ci_time < <(run ci /work/main "CI=true bash .ci/run")
say "CI=true bash .ci/run: exit status $ci_status in $ci_time s"
say "scripts/run-main-job.sh (log: $logs/main-job.log)"
read -r job_status job_time < <(run main-job /job/main "scripts/run-main-job.sh")
say "scripts/run-main-job.sh: exit status $job_status in $job_time s"

summary="commit $commit on $(date -u +%Y-%m-%d), libexpat1 $(in_root dpkg-query -W -f='${Version}' libexpat1):"
summary+=" root set up in $setup s; CI=true bash .ci/run: status $ci_status, $ci_time s;"
summary+=" scripts/run-main-job.sh: status $job_status, $job_time s"
echo "$summary" | tee "$logs/summary.txt"
unmount_all
if [ "$ci_status" = 0 ] && [ "$job_status" = 0 ]; then
  [ "$keep" = 1 ] || remove_root
  exit 0
fi
say "the logs are in $logs; the root is kept in $root"
exit 1
