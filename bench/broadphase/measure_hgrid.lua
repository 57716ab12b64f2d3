--- A quick measure of the hierarchical grid alone (the harness, bench/broadphase.lua, compares
--- the candidates): N boxes of 8-28 px in a square of side 40 sqrt(N), each moving 0.5-2 px
--- a frame and bouncing off the border. Prints ms per frame (update every box, then find
--- every pair), KB per proxy and KB allocated per frame (GC stopped, JIT on). From the
--- repository root:
---   luajit bench/broadphase/measure_hgrid.lua [--n 1000,5000,20000] [--frames 100] [--mixed]
--- (--mixed: 1 % platforms of 200-2,000 px, 10 % bullets of 1 px moving 8-20 px a frame).
package.path = './?.lua;./?/init.lua;' .. package.path
local HGrid = require('bench.broadphase.hgrid')
local PRNG = require('spec.helpers.prng')

local sqrt, cos, sin, pi = math.sqrt, math.cos, math.sin, math.pi
local clock = os.clock
local jit = rawget(_G, 'jit')

local ns, frames, mixed = { 1000, 5000, 20000 }, 100, false
do
  local i = 1
  while arg[i] do
    if arg[i] == '--n' then
      ns = {}
      for w in arg[i + 1]:gmatch('[^,]+') do ns[#ns + 1] = tonumber(w) end
      i = i + 2
    elseif arg[i] == '--frames' then frames, i = tonumber(arg[i + 1]), i + 2
    elseif arg[i] == '--mixed' then mixed, i = true, i + 1
    else error('unknown option ' .. arg[i]) end
  end
end

local function run(n)
  local rng = PRNG.new(42)
  local side = 40 * sqrt(n)
  local x, y, w, h, vx, vy = {}, {}, {}, {}, {}, {}
  for i = 1, n do
    x[i], y[i] = rng:range(0, side), rng:range(0, side)
    w[i], h[i] = rng:range(8, 28), rng:range(8, 28)
    local speed, a = rng:range(0.5, 2), rng:range(-pi, pi)
    if mixed then
      if i % 100 == 0 then
        w[i], h[i], speed = rng:range(200, 2000), 20, 0
        if rng:next() < 0.5 then w[i], h[i] = h[i], w[i] end
      elseif i % 10 == 0 then
        w[i], h[i], speed = 1, 1, rng:range(8, 20)
      end
    end
    vx[i], vy[i] = speed * cos(a), speed * sin(a)
  end
  collectgarbage('collect')
  collectgarbage('collect')
  local before = collectgarbage('count')
  local bp = HGrid.new()
  for i = 1, n do bp:insert(x[i], y[i], x[i] + w[i], y[i] + h[i]) end
  local out = {}
  local function frame()
    for i = 1, n do
      local nx, ny = x[i] + vx[i], y[i] + vy[i]
      if nx < 0 or nx > side then vx[i] = -vx[i] end
      if ny < 0 or ny > side then vy[i] = -vy[i] end
      x[i], y[i] = nx, ny
      bp:update(i, nx, ny, nx + w[i], ny + h[i])
    end
    return bp:pairs(out)
  end
  for _ = 1, 20 do frame() end -- warm up (and grow every array)
  collectgarbage('collect')
  local kbProxy = (collectgarbage('count') - before) / n
  -- time: best of 3 runs of `frames` frames
  local best = math.huge
  local np = 0
  for _ = 1, 3 do
    local t0 = clock()
    for _ = 1, frames do np = frame() end
    local t = (clock() - t0) / frames
    if t < best then best = t end
  end
  -- garbage per frame, GC stopped
  collectgarbage('collect')
  collectgarbage('stop')
  local g0 = collectgarbage('count')
  for _ = 1, frames do frame() end
  local kbFrame = (collectgarbage('count') - g0) / frames
  collectgarbage('restart')
  print(('%-8s N=%-6d %8.3f ms/frame  %6d pairs  %6.3f KB/proxy  %8.4f KB/frame'):format(
    jit and jit.version or _VERSION, n, best * 1000, np, kbProxy, kbFrame))
end

for _, n in ipairs(ns) do run(n) end
