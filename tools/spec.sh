#!/usr/bin/env bash
# Run the busted suite under each Lua VM given, print each VM's result and a total.
# Fails when a VM is missing, when its run reports no summary, or when anything failed.
set -u
busted=$(command -v busted) || { echo "busted not found (apt-get install lua-busted)" >&2; exit 1; }
passed=0; failed=0; status=0; ran=()
log=$(mktemp); trap 'rm -f "$log"' EXIT
for vm in "$@"; do
  if ! command -v "$vm" >/dev/null 2>&1; then
    echo "== $vm: NOT FOUND" >&2; status=1; continue
  fi
  echo "== busted under $vm ($("$vm" -v 2>&1 | head -n 1))"
  "$vm" "$busted" --output=utfTerminal >"$log" 2>&1
  rc=$?
  line=$(grep -E '^[0-9]+ success(es)? / [0-9]+ failures? / [0-9]+ errors? / [0-9]+ pending' "$log" | tail -n 1)
  if [ -z "$line" ]; then
    cat "$log"; echo "== $vm: no test summary (exit $rc)" >&2; status=1; continue
  fi
  [ $rc -ne 0 ] && cat "$log"
  read -r s f e <<<"$(echo "$line" | awk -F' / ' '{ split($1,a," "); split($2,b," "); split($3,c," "); print a[1], b[1], c[1] }')"
  echo "$vm: $s passed, $((f + e)) failed"
  passed=$((passed + s)); failed=$((failed + f + e))
  [ $rc -ne 0 ] && status=1
  ran+=("$vm")
done
echo "== VMs run: ${ran[*]}"
echo "total: $passed passed, $failed failed"
exit $status
