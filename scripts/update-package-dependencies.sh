#!/usr/bin/env bash
# Rewrites package_info/Flow_aligned_surfaces/dependencies the way CGAL generates its own
# packages' files: every CGAL package that owns a header included, directly or not, by a
# header of include/, and the package itself, sorted.  Each public and internal header is
# preprocessed alone (g++ -M); the owner of an installed CGAL header is the package named
# in its `$URL$` line (CGAL releases and Debian's libcgal-dev keep it).
#
# Usage: scripts/update-package-dependencies.sh    # then review with git diff  (--help: this help)
#
# Needs the headers' own dependencies (Eigen, VTK, libpng, ...): a header that does not
# preprocess stops the script rather than leave its packages out.
set -euo pipefail
source "$(dirname "$0")/lib/help.sh"
exit_if_help_asked "$@"
export LC_ALL=C   # the order of sort, as in CGAL's own files

root="$(cd "$(dirname "$0")/.." && pwd)"
out="$root/package_info/Flow_aligned_surfaces/dependencies"
cgal_include="${CGAL_INCLUDE_DIR:-/usr/include}"
vtk_include="$(ls -d /usr/include/vtk-9* 2>/dev/null | sort -V | tail -n 1 || true)"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

cd "$root/include"
find CGAL/Flow_aligned_surfaces -name '*.h' | sort | while read -r header; do
  printf '#include <%s>\n' "$header" > "$work/header.cpp"
  if ! g++ -std=c++17 -M -I"$root/include" -I"$cgal_include" -I/usr/include/eigen3 \
         -I/usr/include/suitesparse ${vtk_include:+-I"$vtk_include"} \
         "$work/header.cpp" > "$work/header.d" 2> "$work/header.err"; then
    echo "$header does not preprocess alone:" >&2
    cat "$work/header.err" >&2
    exit 1
  fi
  tr ' \\' '\n\n' < "$work/header.d" | grep "^$cgal_include/CGAL/" || true
done | sort -u > "$work/cgal_headers"

{
  echo Flow_aligned_surfaces
  while read -r file; do
    owner="$(grep -m 1 -o 'cgal/blob/[^/]*/[A-Za-z0-9_]*/' "$file" | cut -d / -f 4 || true)"
    if [ -z "$owner" ]; then
      echo "no \$URL\$ line names the CGAL package of $file" >&2
      exit 1
    fi
    echo "$owner"
  done < "$work/cgal_headers"
} | sort -u > "$work/dependencies"
mv "$work/dependencies" "$out"

echo "$out: $(wc -l < "$out") packages, from $(wc -l < "$work/cgal_headers") CGAL headers"
