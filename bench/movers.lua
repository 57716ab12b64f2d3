--- Many movers: every body of a world moved by its library's move every frame, strike's
--- S.pace:move beside bump's and slick's world:move (issue 21, "Many movers"). In bench/move.lua
--- one body moves among static ones, so strike's move keeps its candidates from move to move;
--- here every body moves, as every enemy of a game does, and that never applies. Not part of
--- make test. From the repository root, under any VM (`make bench-movers`; `make bench` runs it
--- too, under LuaJIT with LÖVE's limits and with the stock ones, and under Lua 5.4):
---   luajit bench/movers.lua [--n 2000,10000] [--frames 30] [--only strike,bump,slick] [--save]
---                           [--jit love|stock] [--peer-jit]
--- Libraries (--only): strike (S.trikers colliders in S.pace) and the peers found in
--- $STRIKE_PEERS (checkouts named bump.lua and slick, never part of this repository), through
--- bench/adapters/movers_*.lua. LuaJIT runs with LÖVE's JIT limits (as a game does) or with the
--- standalone interpreter's stock ones (--jit stock: 1,000 traces, 512 KB of machine code), and
--- every row says how many times LuaJIT flushed its whole trace cache during the timed frames
--- (jit.attach): a flush throws away every compiled trace, and a workload that flushes again
--- and again runs mostly in the interpreter. slick runs with the JIT off on LuaJIT, as in
--- bench/move.lua (it crashes LuaJIT 2.1.0-beta3 at random with it on), unless --peer-jit.
---
--- The world, the same numbers for every library (seeded, spec/helpers/prng.lua, the same on
--- every VM), for each N:
---   square  side 40 sqrt(N) px (one mover per 1,600 px²), closed by four border walls 64 px
---           thick just outside it;
---   walls   N / 10 static boxes, each 8-24 px thick and 40-160 px long, horizontal or vertical,
---           centred uniformly in the square;
---   movers  N bodies, odd ones boxes 8-16 px a side, even ones capsules (strike:
---           S.trikers.Capsule, w 8-12 px, h w to 2w, caps included; bump and slick, which
---           have no capsules, move their w x h bounding box), placed uniformly where they
---           overlap no wall and no mover placed before (1 px clear);
---   frames  every mover, in order, moved by space:move / world:move toward its centre plus its
---           velocity (1-3 px a frame in a seeded direction), no filter (every library's
---           default response, 'slide'); a mover whose move reports a collision takes the next
---           direction of its own seeded list for the next frame.
--- Measured, per library and N, in a freshly built world (then a full GC and, on LuaJIT, the
--- trace cache flushed): WARMUP frames, then --frames frames timed in three blocks (os.clock
--- around each block: µs per move, best and worst block); collisions per move and px moved per
--- move over the timed frames, to show the workloads are comparable; LuaJIT trace flushes and
--- aborts during the timed frames. Then strike's time over each peer's (below 1: strike
--- faster). --save writes every number to bench/results/movers-<vm>.csv (movers-luajit-stock.csv
--- with --jit stock), in the format of the other results files.
package.path = './?.lua;./?/init.lua;' .. package.path

local PRNG = require('spec.helpers.prng')
local H = require('bench.harness')
local fmt, tableOut, fullGC = H.fmt, H.tableOut, H.fullGC

local clock = os.clock
local jit = rawget(_G, 'jit')
local sqrt, cos, sin, pi, min, max, huge, floor = math.sqrt, math.cos, math.sin, math.pi, math.min, math.max,
  math.huge, math.floor

local opts = { n = { 2000, 10000 }, frames = 30, only = nil, save = false, jit = nil, peerJit = false }
do
  local list = H.list
  local i = 1
  while arg[i] do
    local a, v = arg[i], arg[i + 1]
    if a == '--n' then
      opts.n = {}
      for _, s in ipairs(list(v)) do
        local n = tonumber(s)
        if not n or n < 10 or n % 10 ~= 0 then error('--n must list multiples of 10') end
        opts.n[#opts.n + 1] = n
      end
      i = i + 1
    elseif a == '--frames' then
      opts.frames = tonumber(v)
      if not opts.frames or opts.frames < 3 or opts.frames % 3 ~= 0 then error('--frames must be a multiple of 3') end
      i = i + 1
    elseif a == '--only' then
      opts.only = {}
      for _, name in ipairs(list(v)) do opts.only[name] = true end
      i = i + 1
    elseif a == '--save' then opts.save = true
    elseif a == '--jit' then opts.jit = v; i = i + 1
    elseif a == '--peer-jit' then opts.peerJit = true
    else error('unknown option ' .. a) end
    i = i + 1
  end
end

-- LuaJIT's limits: LÖVE's by default (LÖVE 11.4's boot.lua: maxtrace 2000, maxrecord 8000,
-- maxmcode 16384 KB), or the standalone interpreter's own with --jit stock.
local JIT_LIMITS = H.jitLimits(opts.jit)

local WARMUP = 5
local vmName = jit and jit.version or _VERSION
local vmFile = jit and ('luajit' .. (JIT_LIMITS == 'stock' and '-stock' or '')) or _VERSION:gsub('Lua ', 'lua')

local function wanted(name) return not opts.only or opts.only[name] end
local function note(s) io.stderr:write(s, '\n') io.stderr:flush() end

-- Libraries: strike, then the peers found.
local libs, skipped = {}, {}
if wanted('strike') then
  local ok, A = pcall(require, 'bench.adapters.movers_strike')
  if ok then libs[#libs + 1] = A else skipped[#skipped + 1] = 'strike (' .. tostring(A) .. ')' end
end
H.peers({ { 'bump.lua', 'bump', 'bench.adapters.movers_bump' },
  { 'slick', 'slick', 'bench.adapters.movers_slick' } }, wanted, libs, skipped,
  'bump, slick (set STRIKE_PEERS to a folder with bump.lua and slick checkouts)')

---------------------------------------------------------------------------------------------
-- The world.

-- Boxes by centre and size in a uniform grid of CELL px cells, to place movers clear of
-- everything placed before them without a quadratic search.
local CELL = 64
local function grid() return { cells = {} } end
local function cellKey(i, j) return i * 1000003 + j end
local function gridAdd(g, k, x0, y0, x1, y1)
  for i = floor(x0 / CELL), floor(x1 / CELL) do
    for j = floor(y0 / CELL), floor(y1 / CELL) do
      local key = cellKey(i, j)
      local c = g.cells[key]
      if not c then
        c = {}
        g.cells[key] = c
      end
      c[#c + 1] = k
    end
  end
end
local function gridClear(g, boxes, x0, y0, x1, y1)
  for i = floor(x0 / CELL), floor(x1 / CELL) do
    for j = floor(y0 / CELL), floor(y1 / CELL) do
      local c = g.cells[cellKey(i, j)]
      if c then
        for _, k in ipairs(c) do
          local b = boxes[k]
          if b[1] < x1 and b[3] > x0 and b[2] < y1 and b[4] > y0 then return false end
        end
      end
    end
  end
  return true
end

-- The world of n movers: w.side; walls (centres wx, wy, sizes ww, wh; the four borders first);
-- movers (centres x, y, sizes w, h, capsule[i] for the capsules); per mover its speed and its
-- list of TURNS directions (dirX, dirY at (i - 1) * TURNS + k).
local TURNS = 64
local function makeWorld(n)
  local rng = PRNG.new(20261121 + n)
  local side = 40 * sqrt(n)
  local w = { n = n, side = side, wx = {}, wy = {}, ww = {}, wh = {}, x = {}, y = {}, w = {}, h = {}, capsule = {},
    speed = {}, dirX = {}, dirY = {} }
  local T = 64
  local borders = { { side / 2, -T / 2, side + 2 * T, T }, { side / 2, side + T / 2, side + 2 * T, T },
    { -T / 2, side / 2, T, side }, { side + T / 2, side / 2, T, side } }
  local g, boxes = grid(), {}
  local function addBox(x, y, bw, bh)
    local b = { x - bw / 2, y - bh / 2, x + bw / 2, y + bh / 2 }
    boxes[#boxes + 1] = b
    gridAdd(g, #boxes, b[1], b[2], b[3], b[4])
  end
  for _, b in ipairs(borders) do
    local k = #w.wx + 1
    w.wx[k], w.wy[k], w.ww[k], w.wh[k] = b[1], b[2], b[3], b[4]
  end
  for _ = 1, n / 10 do
    local thick, long = rng:range(8, 24), rng:range(40, 160)
    local bw, bh = thick, long
    if rng:int(0, 1) == 1 then bw, bh = long, thick end
    local x, y = rng:range(0, side), rng:range(0, side)
    local k = #w.wx + 1
    w.wx[k], w.wy[k], w.ww[k], w.wh[k] = x, y, bw, bh
    addBox(x, y, bw, bh)
  end
  for i = 1, n do
    local bw, bh
    if i % 2 == 0 then
      bw = rng:range(8, 12)
      bh = rng:range(bw, 2 * bw)
      w.capsule[i] = true
    else
      bw, bh = rng:range(8, 16), rng:range(8, 16)
      w.capsule[i] = false
    end
    local x, y
    repeat
      x, y = rng:range(bw / 2 + 1, side - bw / 2 - 1), rng:range(bh / 2 + 1, side - bh / 2 - 1)
    until gridClear(g, boxes, x - bw / 2 - 1, y - bh / 2 - 1, x + bw / 2 + 1, y + bh / 2 + 1)
    addBox(x, y, bw, bh)
    w.x[i], w.y[i], w.w[i], w.h[i] = x, y, bw, bh
    w.speed[i] = rng:range(1, 3)
    for k = 1, TURNS do
      local a = rng:range(-pi, pi)
      w.dirX[(i - 1) * TURNS + k], w.dirY[(i - 1) * TURNS + k] = cos(a), sin(a)
    end
  end
  return w
end

---------------------------------------------------------------------------------------------
-- Running.

-- LuaJIT trace events while `counting`.
local flushes, aborts, counting = 0, 0, false
if jit and jit.attach then
  jit.attach(function(what)
    if counting then
      if what == 'flush' then flushes = flushes + 1
      elseif what == 'abort' then aborts = aborts + 1 end
    end
  end, 'trace')
end


local function jitOff(lib) return jit and lib.jitOff and not opts.peerJit end

-- Frames f0 + 1 .. f0 + count of world w through st; the state (positions, turn counters) in
-- `run`. Returns the collisions reported and the px moved.
local function frames(st, w, run, count)
  local move, n, dirX, dirY, speed = st.move, w.n, w.dirX, w.dirY, w.speed
  local x, y, turn = run.x, run.y, run.turn
  local cols, dist = 0, 0
  for _ = 1, count do
    for i = 1, n do
      local d = (i - 1) * TURNS + turn[i]
      local s, px, py = speed[i], x[i], y[i]
      local ax, ay, c = move(i, px + s * dirX[d], py + s * dirY[d])
      if c > 0 then turn[i] = turn[i] % TURNS + 1 end
      cols = cols + c
      dist = dist + sqrt((ax - px) ^ 2 + (ay - py) ^ 2)
      x[i], y[i] = ax, ay
    end
  end
  return cols, dist
end

local function measure(lib, w)
  fullGC()
  if jitOff(lib) then jit.off() end
  local t0 = clock()
  local st = lib.new(w)
  local buildMs = (clock() - t0) * 1000
  local run = { x = {}, y = {}, turn = {} }
  for i = 1, w.n do run.x[i], run.y[i], run.turn[i] = w.x[i], w.y[i], 1 end
  fullGC()
  if jit then jit.flush() end
  frames(st, w, run, WARMUP)
  local block = opts.frames / 3
  local best, worst, cols, dist = huge, 0, 0, 0
  flushes, aborts, counting = 0, 0, true
  for _ = 1, 3 do
    local c0 = clock()
    local c, d = frames(st, w, run, block)
    local t = clock() - c0
    best, worst, cols, dist = min(best, t), max(worst, t), cols + c, dist + d
  end
  counting = false
  if jitOff(lib) then jit.on() end
  local moves = w.n * block
  return { lib = lib.name, best = best * 1e6 / moves, worst = worst * 1e6 / moves, cols = cols / (3 * moves),
    dist = dist / (3 * moves), flushes = jit and flushes, aborts = jit and aborts, build = buildMs,
    jitOff = jitOff(lib) and true or nil }
end

---------------------------------------------------------------------------------------------
-- Tables.

local csv = {}
local function put(lib, n, metric, value) csv[#csv + 1] = { lib, n, metric, value } end

local t00 = os.time()
local title = ('strike movers bench — %s%s'):format(vmName, jit and (' (JIT limits: ' .. JIT_LIMITS .. ')') or '')
note(title)
print(title)
for _, l in ipairs(libs) do
  local off = jitOff(l) and '; JIT OFF (it crashes LuaJIT here; --peer-jit: on)' or ''
  print(('  %-7s %s%s'):format(l.name, l.note, off))
end
print()
for _, n in ipairs(opts.n) do
  local w = makeWorld(n)
  local rows = {}
  for _, lib in ipairs(libs) do
    local c0 = clock()
    local ok, r = pcall(measure, lib, w)
    if not ok then
      r = { lib = lib.name, err = tostring(r) }
      if jitOff(lib) then jit.on() end
    end
    rows[#rows + 1] = r
    if r.err then note(('  N %d %-7s ERROR: %s'):format(n, lib.name, r.err))
    else
      note(('  N %d %-7s %8.2f µs/move (worst %.2f) %6.3f collisions/move, flushes %s  %.1f s'):format(n, lib.name,
        r.best, r.worst, r.cols, tostring(r.flushes), clock() - c0))
    end
    fullGC()
  end
  print(('%d movers (boxes and capsules) and %d walls in a %.0f px square, every mover moved every frame (%d '
    .. 'frames after %d; µs per move, best and worst of three blocks of %d frames)'):format(n, n / 10, w.side,
    opts.frames, WARMUP, opts.frames / 3))
  local body = {}
  for _, r in ipairs(rows) do
    if r.err then
      body[#body + 1] = { r.lib, 'ERROR', r.err, '', '', '', '', '' }
    else
      put(r.lib, n, 'us_per_move_best', r.best)
      put(r.lib, n, 'us_per_move_worst', r.worst)
      put(r.lib, n, 'collisions_per_move', r.cols)
      put(r.lib, n, 'px_moved_per_move', r.dist)
      put(r.lib, n, 'build_ms', r.build)
      if jit then
        put(r.lib, n, 'trace_flushes', r.flushes)
        put(r.lib, n, 'trace_aborts', r.aborts)
      end
      body[#body + 1] = { r.lib .. (r.jitOff and ' (JIT off)' or ''), fmt(r.best), fmt(r.worst), fmt(r.cols, 3),
        fmt(r.dist, 2), jit and (r.flushes .. ' / ' .. r.aborts) or '—', fmt(r.build, 1) }
    end
  end
  tableOut({ 'library', 'µs/move best', 'worst', 'collisions/move', 'px moved/move', 'trace flushes / aborts',
    'build ms' }, body)
  local s
  for _, r in ipairs(rows) do if r.lib == 'strike' and not r.err then s = r end end
  if s then
    local head, cells = {}, {}
    for _, p in ipairs(rows) do
      if p ~= s and not p.err then
        local ratio = s.best / p.best
        head[#head + 1] = 'strike ÷ ' .. p.lib .. (p.jitOff and ' (JIT off)' or '')
        cells[#cells + 1] = ('%.2f×'):format(ratio)
        put('strike', n, 'time_over_' .. p.lib, ratio)
      end
    end
    if #head > 0 then
      print('Side by side (best µs per move; strike ÷ peer = strike\'s time over the peer\'s, below 1 = strike faster)')
      tableOut(head, { cells })
    end
  end
end
if #skipped > 0 then print('skipped: ' .. table.concat(skipped, '; ')) end
print(('(%d s in all)'):format(os.time() - t00))

if opts.save then
  local path = 'bench/results/movers-' .. vmFile .. '.csv'
  local f = assert(io.open(path, 'w'))
  f:write('vm,section,library,n,metric,value\n')
  for _, r in ipairs(csv) do
    f:write(('%s,%s,%s,%d,%s,%.6g\n'):format(vmName .. (jit and (' ' .. JIT_LIMITS) or ''), 'movers', r[1], r[2],
      r[3], r[4]))
  end
  f:close()
  print('saved ' .. path)
end
