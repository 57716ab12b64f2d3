#!/usr/bin/env bash
# Run the busted suite under each Lua VM given, print each VM's result and a total.
# Fails when a VM is missing, when its run reports no summary, or when anything failed.
# The VMs run side by side, SPEC_JOBS at a time (default: the machine's cores), each into a
# log of its own; the results are printed in the order the VMs were given.
set -u
busted=$(command -v busted) || { echo "busted not found (apt-get install lua-busted)" >&2; exit 1; }
jobs=${SPEC_JOBS:-$(nproc 2>/dev/null || echo 1)}
[ "$jobs" -ge 1 ] 2>/dev/null || jobs=1
passed=0; failed=0; status=0; ran=()
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
vms=()
for vm in "$@"; do
  if ! command -v "$vm" >/dev/null 2>&1; then
    echo "== $vm: NOT FOUND" >&2; status=1; continue
  fi
  vms+=("$vm")
done
# start them, at most $jobs at once, the last given first (make test gives luajit and lua5.4
# last, and they run every random case: spec/helpers/budget.lua), so that the longest start first
running=0
for ((i = ${#vms[@]} - 1; i >= 0; i--)); do
  vm=${vms[$i]}
  if [ "$running" -ge "$jobs" ]; then wait -n; running=$((running - 1)); fi
  ( "$vm" "$busted" --output=utfTerminal >"$dir/$vm.log" 2>&1; echo $? >"$dir/$vm.rc" ) &
  running=$((running + 1))
done
wait
for vm in "${vms[@]}"; do
  log="$dir/$vm.log"
  rc=$(cat "$dir/$vm.rc" 2>/dev/null || echo 1)
  line=$(grep -E '^[0-9]+ success(es)? / [0-9]+ failures? / [0-9]+ errors? / [0-9]+ pending' "$log" | tail -n 1)
  echo "== busted under $vm ($("$vm" -v 2>&1 | head -n 1)): $(echo "$line" | sed -nE 's/.*: ([0-9.]+) seconds.*/\1 s/p')"
  if [ -z "$line" ]; then
    cat "$log"; echo "== $vm: no test summary (exit $rc)" >&2; status=1; continue
  fi
  [ "$rc" -ne 0 ] && cat "$log"
  read -r s f e <<<"$(echo "$line" | awk -F' / ' '{ split($1,a," "); split($2,b," "); split($3,c," "); print a[1], b[1], c[1] }')"
  echo "$vm: $s passed, $((f + e)) failed"
  passed=$((passed + s)); failed=$((failed + f + e))
  [ "$rc" -ne 0 ] && status=1
  ran+=("$vm")
done
echo "== VMs run: ${ran[*]}"
echo "total: $passed passed, $failed failed"
exit $status
