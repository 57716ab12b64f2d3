--- S.tiled's load time (issue 22): a 200 x 200 map of 16 px tiles, 40 % of them solid at
--- random (two tiles alternating), and 1,000 objects of every kind (bench/workloads.lua,
--- tiledMap), loaded into a fresh space. Run from the repository root:
---   luajit bench/tiled.lua [--size N] [--density D] [--objects N] [--seed N] [--runs N]
---                          [--jit love|stock] [--save]
--- or `make bench` (LuaJIT and Lua 5.4). Prints, per part of the map (tiles, objects, both):
--- the first load in this process (LuaJIT compiles as it goes: what a game's first level
--- costs) and the best of --runs loads after it (default 5), in milliseconds, and what was
--- loaded: bodies, the tile layer's regions and rectangles. The regions are checked against
--- an independent flood fill of the solid cells (4-connected), and every body count against
--- it plus the objects, before anything is timed ("ok"). --save writes bench/results/tiled-
--- <vm>.csv.
---
--- LuaJIT's limits are LÖVE's by default, as a game runs (LÖVE 11.4's boot.lua raises them:
--- maxtrace 2000, maxrecord 8000, maxmcode 16384 KB; bench/space.lua does the same), or the
--- standalone interpreter's own with --jit stock. Each part runs in a process of its own when
--- run by this script with --part (it starts itself once per part, so that one part's traces
--- never help or crowd out another's).
package.path = './?.lua;./?/init.lua;' .. package.path

local jit = rawget(_G, 'jit')
local clock = os.clock

local opts = { size = 200, density = 0.4, objects = 1000, seed = 7, runs = 5, jit = 'love', save = false }
do
  local i = 1
  while arg[i] do
    local a, v = arg[i], arg[i + 1]
    if a == '--size' then opts.size = tonumber(v); i = i + 1
    elseif a == '--density' then opts.density = tonumber(v); i = i + 1
    elseif a == '--objects' then opts.objects = tonumber(v); i = i + 1
    elseif a == '--seed' then opts.seed = tonumber(v); i = i + 1
    elseif a == '--runs' then opts.runs = tonumber(v); i = i + 1
    elseif a == '--jit' then opts.jit = v; i = i + 1
    elseif a == '--part' then opts.part = v; i = i + 1
    elseif a == '--save' then opts.save = true
    else error('unknown option ' .. a) end
    i = i + 1
  end
end
if opts.jit ~= 'love' and opts.jit ~= 'stock' then error('--jit must be love or stock') end

local vmName = jit and jit.version or _VERSION
local vmFile = jit and 'luajit' or _VERSION:gsub('Lua ', 'lua')

-- The regions of the solid cells, by a flood fill over 4-neighbours (no code of strike's).
local function floodRegions(data, n)
  local seen, regions = {}, 0
  local stack = {}
  for start = 1, n * n do
    if data[start] ~= 0 and not seen[start] then
      regions = regions + 1
      seen[start] = true
      local top = 1
      stack[1] = start
      while top > 0 do
        local i = stack[top]
        top = top - 1
        local c, r = (i - 1) % n, math.floor((i - 1) / n)
        local nb = { c > 0 and i - 1, c < n - 1 and i + 1, r > 0 and i - n, r < n - 1 and i + n }
        for k = 1, 4 do
          local j = nb[k]
          if j and data[j] ~= 0 and not seen[j] then
            seen[j] = true
            top = top + 1
            stack[top] = j
          end
        end
      end
    end
  end
  return regions
end

local PARTS = { 'tiles', 'objects', 'both' }

-- One part, in this process: its map, the check, the first load and the best of the rest.
local function runPart(part)
  require('bench.harness').jitLimits(opts.jit)
  local S = require('strike')
  local W = require('bench.workloads')
  local map = W.tiledMap(opts.size, opts.density, opts.objects, opts.seed)
  local regions = floodRegions(map.layers[1].data, opts.size)
  local nobj = #map.layers[2].objects
  if part == 'tiles' then table.remove(map.layers, 2); nobj = 0 end
  if part == 'objects' then table.remove(map.layers, 1); regions = 0 end
  collectgarbage('collect')
  local t0 = clock()
  local level = S.tiled(map, S.pace())
  local first = clock() - t0
  local rects, nreg = 0, 0
  for _, body in ipairs(level.bodies) do
    if level.objectOf[body].tiles then
      nreg = nreg + 1
      rects = rects + body:getShapeCount()
    end
  end
  local ok = nreg == regions and #level.bodies == regions + nobj
  local best = math.huge
  for _ = 1, opts.runs do
    collectgarbage('collect')
    local space = S.pace()
    local t1 = clock()
    S.tiled(map, space)
    best = math.min(best, clock() - t1)
  end
  return first, best, #level.bodies, nreg, rects, ok
end

if opts.part then
  local first, best, bodies, nreg, rects, ok = runPart(opts.part)
  io.write(('%.17g %.17g %d %d %d %s\n'):format(first, best, bodies, nreg, rects, tostring(ok)))
  os.exit(0)
end

-- Each part in a process of its own (this script again, with --part), under this VM.
local function interpreter()
  local i, name = 0, arg[0]
  while arg[i - 1] do i, name = i - 1, arg[i - 1] end
  return name
end
local vm = interpreter()
local rows = {}
io.stderr:write(('S.tiled on a %d x %d map, %d %% solid, %d objects, seed %d (%s, JIT limits: %s)\n'):format(
  opts.size, opts.size, math.floor(opts.density * 100 + 0.5), opts.objects, opts.seed, vmName,
  jit and opts.jit or 'none'))
for _, part in ipairs(PARTS) do
  local cmd = ('%s bench/tiled.lua --part %s --size %d --density %s --objects %d --seed %d --runs %d --jit %s'):format(
    vm, part, opts.size, tostring(opts.density), opts.objects, opts.seed, opts.runs, opts.jit)
  local p = assert(io.popen(cmd, 'r'))
  local line = p:read('*l')
  p:close()
  local first, best, bodies, nreg, rects, ok = (line or ''):match('^(%S+) (%S+) (%d+) (%d+) (%d+) (%a+)$')
  if not first then error('part ' .. part .. ' failed: ' .. tostring(line)) end
  rows[#rows + 1] = { part = part, first = tonumber(first) * 1000, best = tonumber(best) * 1000,
    bodies = tonumber(bodies), regions = tonumber(nreg), rects = tonumber(rects), ok = ok == 'true' }
end

print(('S.tiled — %s%s — %d x %d tiles, %d %% solid, %d objects, seed %d'):format(vmName,
  jit and (', JIT limits: ' .. opts.jit) or '', opts.size, opts.size, math.floor(opts.density * 100 + 0.5),
  opts.objects, opts.seed))
print('| part | first load (ms) | best of ' .. opts.runs .. ' after (ms) | bodies | regions | rectangles | ok |')
print('|---|---|---|---|---|---|---|')
for _, r in ipairs(rows) do
  print(('| %s | %.1f | %.1f | %d | %d | %d | %s |'):format(r.part, r.first, r.best, r.bodies, r.regions, r.rects,
    r.ok and 'yes' or 'NO'))
end

if opts.save then
  local path = 'bench/results/tiled-' .. vmFile .. (jit and opts.jit == 'stock' and '-stock' or '') .. '.csv'
  local f = assert(io.open(path, 'w'))
  f:write('vm,jit_limits,size,density,objects,seed,part,first_ms,best_ms,bodies,regions,rectangles,ok\n')
  for _, r in ipairs(rows) do
    f:write(('%s,%s,%d,%s,%d,%d,%s,%.2f,%.2f,%d,%d,%d,%s\n'):format(vmName, jit and opts.jit or 'none', opts.size,
      tostring(opts.density), opts.objects, opts.seed, r.part, r.first, r.best, r.bodies, r.regions, r.rects,
      tostring(r.ok)))
  end
  f:close()
  print('saved ' .. path)
end
for _, r in ipairs(rows) do
  if not r.ok then os.exit(1) end
end
