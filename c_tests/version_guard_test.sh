#!/usr/bin/env bash
# Each v3 adapter header, compiled against each Box2D (2.4, v3.1, v3.2): against its own it
# compiles warning-free; against another it stops at one line, its #error naming the version
# it needs, and nothing from inside Box2D's headers.
# Usage: version_guard_test.sh CC BOX2SCENE_INCLUDE BOX2D24_INCLUDE BOX2D31_INCLUDE BOX2D32_INCLUDE
set -euo pipefail
cc=$1 box2scene_include=$2
declare -A engine=([2.4]=$3 [3.1]=$4 [3.2]=$5)
declare -A needs=([box2d3]=3.1 [box2d32]=3.2)
source=$(mktemp --suffix=.c)
trap 'rm -f "$source"' EXIT
failures=0
for header in box2d3 box2d32; do
  printf '#include <box2scene/%s.h>\nint main(void) { return 0; }\n' "$header" >"$source"
  for version in 2.4 3.1 3.2; do
    status=0
    errors=$("$cc" -std=c11 -Wall -Wextra -fsyntax-only -I"${engine[$version]}" \
      -I"$box2scene_include" "$source" 2>&1) || status=$?
    if [ "$version" = "${needs[$header]}" ]; then
      if [ "$status" -ne 0 ] || [ -n "$errors" ]; then
        echo "FAIL: box2scene/$header.h against Box2D $version: $errors"; failures=$((failures + 1))
      fi
      continue
    fi
    expected="error: #error \"box2scene/$header.h needs Box2D ${needs[$header]}, and <box2d/box2d.h> is another version"
    count=$(grep -c 'error:' <<<"$errors" || true)
    if [ "$status" -eq 0 ] || [ "$count" -ne 1 ] || ! grep -qF "$expected" <<<"$errors"; then
      echo "FAIL: box2scene/$header.h against Box2D $version, $count errors:"; echo "$errors"
      failures=$((failures + 1))
    fi
  done
done
[ "$failures" -eq 0 ] && echo "version_guard_test: both headers, three engines: as expected"
exit "$failures"
