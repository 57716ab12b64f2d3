#!/usr/bin/env bash
# The rockspec check of `make test`: `luarocks lint` on strike-scm-1.rockspec, then
# `luarocks make` into a temporary tree (a configuration of its own: its only rocks server an
# empty local directory, so no network; nothing written under $HOME or in the repository), then
#  * the tree holds exactly the files of strike/, each a copy: a Lua file added under strike/
#    without its line in build.modules, or a line whose module name does not match its path,
#    fails here;
#  * under every VM given, from a directory outside the repository and with package.path set to
#    the tree only, `require 'strike'` gives the library, which collides two bodies, and every
#    installed module loads by its name.
# LuaRocks installs pure Lua files for its own Lua version (share/lua/5.1 with Debian's); the
# files do not depend on it, so every VM loads that same directory.
#   bash tools/rockspec-check.sh lua5.1 lua5.2 lua5.3 lua5.4 luajit
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
rockspec=strike-scm-1.rockspec
cd "$here" || exit 1
command -v luarocks >/dev/null 2>&1 || { echo "rockspec-check: luarocks is not installed (Debian: luarocks)" >&2; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/home" "$tmp/run"
cat >"$tmp/config.lua" <<EOF
rocks_trees = { { name = "check", root = "$tmp/tree" } }
rocks_servers = { "$tmp/no-server" }
local_cache = "$tmp/cache"
EOF
rocks() { HOME="$tmp/home" LUAROCKS_CONFIG="$tmp/config.lua" luarocks "$@"; }

rocks lint "$rockspec" || { echo "rockspec-check: luarocks lint $rockspec failed" >&2; exit 1; }
rocks make --tree "$tmp/tree" "$rockspec" >"$tmp/make.log" 2>&1 \
  || { cat "$tmp/make.log" >&2; echo "rockspec-check: luarocks make $rockspec failed" >&2; exit 1; }

# The Lua directory of the tree (share/lua/<version>): there is exactly one.
luadirs=("$tmp"/tree/share/lua/*/)
[ ${#luadirs[@]} -eq 1 ] && [ -d "${luadirs[0]}" ] \
  || { echo "rockspec-check: luarocks make installed no Lua directory under $tmp/tree/share/lua" >&2; exit 1; }
luadir=${luadirs[0]%/}

# The tree against the folder, file by file.
status=0
(cd "$luadir" && find . -type f | sed 's|^\./||' | LC_ALL=C sort) >"$tmp/installed"
find strike -type f -name '*.lua' | LC_ALL=C sort >"$tmp/expected"
while read -r f; do
  m=${f%.lua}; m=${m%/init}; m=${m//\//.}
  echo "rockspec-check: $f is not in $rockspec; add to build.modules: [\"$m\"] = \"$f\"," >&2
  status=1
done < <(LC_ALL=C comm -13 "$tmp/installed" "$tmp/expected")
while read -r f; do
  echo "rockspec-check: $rockspec installs $f, which is not a file of strike/ (a module name that does not match its path?)" >&2
  status=1
done < <(LC_ALL=C comm -23 "$tmp/installed" "$tmp/expected")
while read -r f; do
  cmp -s "$f" "$luadir/$f" || { echo "rockspec-check: the installed $f differs from strike/'s" >&2; status=1; }
done < <(LC_ALL=C comm -12 "$tmp/installed" "$tmp/expected")
[ $status -eq 0 ] || exit 1

# Module names of the installed files (strike/init.lua is `strike`), for the VMs to load.
modules=$(sed -e 's|\.lua$||' -e 's|/init$||' -e 's|/|.|g' "$tmp/installed" | tr '\n' ' ')
for vm in "$@"; do
  if (cd "$tmp/run" && "$vm" -e "
    package.path = '$luadir/?.lua;$luadir/?/init.lua'
    package.cpath = ''
    local S = require 'strike'
    assert(type(S) == 'table' and S.hapes and S.hapes.Circle and S.trikers, 'require strike gave no library')
    local m = S.triking(S.trikers.Rectangle(0, 0, 10), S.trikers.Circle(7, 0, 3))
    assert(m and math.abs(m.x - 1) < 1e-12, 'wrong collision')
    for name in ('$modules'):gmatch('%S+') do
      local mod = require(name)
      assert(mod ~= nil and mod ~= true, name .. ' returned nothing')
    end
    assert(package.loaded.strike == S and not package.loaded['strike.init'], 'strike loaded twice')
  "); then :; else echo "rockspec-check: $vm could not require strike from the installed tree" >&2; status=1; fi
done
[ $status -eq 0 ] && echo "rockspec-check: $rockspec lints, installs the $(wc -l <"$tmp/installed") files of strike/ and loads under: $*"
exit $status
