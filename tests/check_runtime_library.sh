#!/usr/bin/env bash
# The runtime is only the runtime: the libraries an application links (sfx, sfx_shaders,
# sfx_core) hold no CPU reference (sfx::reference) and embed no program that only tests or
# samples use (the names in shader_src/programs_test.txt and programs_scenes.txt).
# Usage: check_runtime_library.sh <shader_src dir> <runtime archive>...
set -euo pipefail
shader_dir=$1
shift
names=$(cat "$shader_dir/programs_test.txt" "$shader_dir/programs_scenes.txt" | awk '!/^#/ && NF {print $1}')
[ -n "$names" ] || { echo "FAILED: no program names read from $shader_dir"; exit 1; }
failed=0
seen=0
for archive in "$@"; do
  [ -f "$archive" ] || { echo "FAILED: $archive does not exist"; failed=1; continue; }
  if refs=$(nm -C "$archive" 2>/dev/null | grep -F 'sfx::reference::'); then
    echo "FAILED: $archive defines or needs CPU reference symbols:"; echo "$refs" | head -5; failed=1
  fi
  # sfxc names each embedded SPIR-V array kSpirv_<program>_<tier>_<stage>.
  symbols=$(nm -C "$archive" 2>/dev/null)
  for name in $names; do
    if printf '%s\n' "$symbols" | grep -Eq -- "kSpirv_${name}_(current|high)_[0-9]+"; then
      echo "FAILED: $archive embeds the program '$name', which is not a runtime program"; failed=1
    fi
  done
  seen=$((seen + $(printf '%s\n' "$symbols" | grep -c 'kSpirv_' || true)))
  echo "checked $archive: $(printf '%s\n' "$symbols" | grep -c 'kSpirv_') embedded SPIR-V stages, $(printf '%s\n' "$symbols" | grep -c ' T ') functions"
done
# The runtime's own programs must show, or the symbol table is not telling (stripped, renamed).
if [ "$seen" -eq 0 ]; then echo "FAILED: no kSpirv_ symbol in any archive: the check cannot see programs"; failed=1; fi
[ $failed -eq 0 ] && echo "runtime libraries hold no reference and no test or sample program"
exit $failed
