#!/usr/bin/env bash
# Seed corpora for the fuzz drivers, written to OUT/scene and OUT/msh:
#   scene: scenes/*.toml, tests/workflows/*.toml, tests/workflows/bad_scenes/*.toml,
#          plus one scene with --set overrides after a "%%" line (see fuzz_scene.cpp);
#   msh:   coarse meshes that `rockfdem mesh` writes for each shipped scene
#          (gmsh 4.1 format, as write_msh gives them) and the hand-written and
#          malformed files the mesh tests write (MSH 2.2).
#
#   bash tests/fuzz/make_corpus.sh OUT [ROCKFDEM_BINARY] [MESH_TEST_BINARY]
#
# The binaries default to the normal build's (build/bin/rockfdem,
# build/tests/mesh/rockfdem_mesh_tests); a missing one is skipped with a note.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:?usage: make_corpus.sh OUT [ROCKFDEM_BINARY] [MESH_TEST_BINARY]}
rockfdem=${2:-$root/build/bin/rockfdem}
mesh_tests=${3:-$root/build/tests/mesh/rockfdem_mesh_tests}
mkdir -p "$out/scene" "$out/msh"

for f in "$root"/scenes/*.toml "$root"/tests/workflows/*.toml "$root"/tests/workflows/bad_scenes/*.toml; do
  cp "$f" "$out/scene/$(basename "$(dirname "$f")")_$(basename "$f")"
done
{ cat "$root/scenes/kirsch-circular.toml"; printf '\n%%%%\nmesh.size_near=0.3\nengine.steps=10\n'; } \
  >"$out/scene/with_overrides.toml"

if [ -x "$rockfdem" ]; then
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  # Coarse versions of every shipped scene, small enough for the fuzzer's
  # input limit (64 KiB).
  mesh_one() {  # name scene --set ...
    local name=$1 scene=$2; shift 2
    if "$rockfdem" mesh "$scene" -o "$tmp/$name" -q "$@" >/dev/null 2>&1; then
      cp "$tmp/$name/mesh.msh" "$out/msh/$name.msh"
    else
      echo "make_corpus.sh: rockfdem mesh $name failed; skipped" >&2
    fi
  }
  mesh_one tunnel "$root/scenes/tunnel-seed.toml" --set mesh.size_near=0.4 --set mesh.size_far=40
  mesh_one kirsch "$root/scenes/kirsch-circular.toml" --set mesh.size_near=3 --set mesh.size_far=20
  mesh_one ucs "$root/scenes/ucs-33k.toml" --set mesh.size_near=0.01
  mesh_one brazilian "$root/scenes/brazilian-disc.toml" --set mesh.size_near=0.008
else
  echo "make_corpus.sh: $rockfdem not built; no meshed seeds" >&2
fi

if [ -x "$mesh_tests" ]; then
  tmp2=$(mktemp -d)
  TEST_TMPDIR=$tmp2/ "$mesh_tests" --gtest_filter='MshUserFile.*' >/dev/null 2>&1 || true
  for f in "$tmp2"/*.msh; do [ -f "$f" ] && cp "$f" "$out/msh/test_$(basename "$f")"; done
  rm -rf "$tmp2"
else
  echo "make_corpus.sh: $mesh_tests not built; no malformed .msh seeds" >&2
fi
echo "seeds: $(ls "$out/scene" | wc -l) scenes, $(ls "$out/msh" | wc -l) .msh files in $out"
