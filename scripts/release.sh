#!/usr/bin/env bash
# Builds the release from clean checkouts of HEAD and proves it reproducible:
#   1. one version everywhere: codegen/project.py's VERSION, CHANGELOG.md has an entry for it;
#   2. two clean clones, in two different folders, each set up and built (scripts/build.sh), with
#      dist/cross-check/ (scripts/make_cross_check.py), dist/ssp/RoundTrip.ssp and
#      dist/ssp/Tumbling.ssp (examples/ssp/);
#   3. every file of the two dist/ folders compared byte for byte (no timestamps or build paths);
#   4. the version attribute of every modelDescription.xml, CMake's project version
#      (build/CMakeCache.txt) and the "version X.Y.Z" of the FMU documentation equal to VERSION;
#   5. the first clone's dist/ in place of dist/ here (its README.md is the committed one), with
#      dist/SHA256SUMS of every file it ships, checked with sha256sum -c.
# Uncommitted changes are not part of a release: commit first. Takes about two builds' time.
#   bash scripts/release.sh
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
fail() {
  echo "release: FAILED: $*" >&2
  [ -z "${work:-}" ] || echo "release: the builds are kept in $work" >&2
  exit 1
}

version=$(sed -n 's/^VERSION = "\(.*\)"$/\1/p' codegen/project.py)
[ -n "$version" ] || fail "no VERSION in codegen/project.py"
[ -f CHANGELOG.md ] || fail "CHANGELOG.md is missing"
grep -Eq "^#+ .*\b${version//./\\.}\b" CHANGELOG.md || fail "CHANGELOG.md has no entry for $version"
[ -z "$(git status --porcelain --untracked-files=no)" ] ||
  echo "release: note: uncommitted changes are left out; the release is HEAD $(git rev-parse --short HEAD)"
commit=$(git rev-parse HEAD)

work=$(mktemp -d)
for side in one two; do
  clone="$work/$side/AngularKinematics"
  git clone -q --no-local "$root" "$clone"
  git -C "$clone" checkout -q "$commit"
  # The Python environment of this checkout, when there is one: the same pinned packages.
  if [ -x .venv/bin/python ]; then ln -s "$(readlink -f .venv)" "$clone/.venv"; fi
  echo "release: building $commit in $clone"
  (
    cd "$clone"
    bash scripts/setup.sh >/dev/null
    bash scripts/build.sh >build.log 2>&1 || { tail -40 build.log; exit 1; }
    # As modules from the clone's root: its own packages come first, not those of the checkout
    # whose .venv it shares (installed editable there).
    .venv/bin/python -m scripts.make_cross_check >/dev/null
    .venv/bin/python -m examples.ssp.make_ssp >/dev/null
    .venv/bin/python -m examples.ssp.make_tumbling_ssp >/dev/null
  ) || fail "the build in $clone failed"
done

one="$work/one/AngularKinematics/dist"
two="$work/two/AngularKinematics/dist"
(cd "$one" && find . -type f | LC_ALL=C sort) >"$work/one.list"
(cd "$two" && find . -type f | LC_ALL=C sort) >"$work/two.list"
cmp -s "$work/one.list" "$work/two.list" || fail "the two builds made different files"
while IFS= read -r file; do
  cmp -s "$one/$file" "$two/$file" || fail "$file differs between the two builds"
done <"$work/one.list"
echo "release: $(wc -l <"$work/one.list") files of dist/ byte-identical in two builds"

cmake_version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$work/one/AngularKinematics/build/CMakeCache.txt")
[ "$cmake_version" = "$version" ] || fail "CMake's project version is $cmake_version, not $version"
for fmu in "$one"/*.fmu "$one"/fmi3/*.fmu; do
  found=$(unzip -p "$fmu" modelDescription.xml | grep -oE '^  version="[^"]*"' | cut -d'"' -f2)
  [ "$found" = "$version" ] || fail "${fmu#"$one"/}: modelDescription.xml version $found, not $version"
  for stated in $(unzip -p "$fmu" documentation/index.html | grep -oE 'version [0-9]+\.[0-9]+\.[0-9]+' |
    cut -d' ' -f2); do
    [ "$stated" = "$version" ] || fail "${fmu#"$one"/}: its documentation says version $stated"
  done
done
echo "release: version $version in codegen, CMake, every modelDescription.xml and documentation"

mkdir -p dist
find dist -mindepth 1 -maxdepth 1 -exec rm -rf {} +  # nothing stale in the release
cp -r "$one"/. dist/
bash scripts/checksums.sh dist
[ "$(wc -l <dist/SHA256SUMS)" = "$(wc -l <"$work/one.list")" ] || fail "dist/SHA256SUMS misses a file"
(cd dist && sha256sum -c --quiet SHA256SUMS) || fail "dist/SHA256SUMS does not verify"
echo "release: dist/ of $commit, dist/SHA256SUMS:"
cat dist/SHA256SUMS
rm -rf "$work"
