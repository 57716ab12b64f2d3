--- Quick measurement of bench/broadphase/tree.lua (the shared harness compares candidates).
---   luajit bench/broadphase/measure_tree.lua [N ...]     (default 1000 5000 20000)
---   lua5.4 bench/broadphase/measure_tree.lua 1000 100000 mixed
--- World: N bodies in a square of side 40 sqrt(N), 8-28 px, each moving 0.5-2 px per
--- frame and bouncing off the border ("mixed": one body in 50 is a 1 px bullet moving 4-8 px,
--- one in 500 a 500-2,000 px platform, still). A frame = update every body + pairs.
--- Reports ms per frame (the best of 3 runs, after a warm-up), pairs and candidates per
--- frame, KB per proxy (tree and pair set, after building) and KB allocated per frame (GC
--- stopped, JIT on), and on LuaJIT the number of trace flushes.
package.path = './?.lua;' .. package.path
local Tree = require('strike.space.tree')
local PRNG = require('spec.helpers.prng')

local clock = os.clock
local jit = rawget(_G, 'jit')
local flushes = 0
if jit and not os.getenv('JITV') then -- (jit.v attaches there too)
  require('jit').attach(function(what) if what == 'flush' then flushes = flushes + 1 end end, 'trace')
end

local sizes, mixed = {}, false
for _, a in ipairs(arg) do
  if a == 'mixed' then mixed = true else sizes[#sizes + 1] = tonumber(a) end
end
if #sizes == 0 then sizes = { 1000, 5000, 20000 } end

local function measure(n)
  local rng = PRNG.new(42)
  local side = 40 * math.sqrt(n)
  local x, y, w, h, vx, vy, id = {}, {}, {}, {}, {}, {}, {}
  for i = 1, n do
    local speed = rng:range(0.5, 2)
    if mixed and i % 50 == 0 then
      w[i], h[i], speed = 1, 1, rng:range(4, 8)
    elseif mixed and i % 500 == 1 then
      w[i], h[i], speed = rng:range(500, 2000), rng:range(10, 40), 0
    else
      w[i], h[i] = rng:range(8, 28), rng:range(8, 28)
    end
    x[i], y[i] = rng:range(0, side - w[i]), rng:range(0, side - h[i])
    local a = rng:range(0, 2 * math.pi)
    vx[i], vy[i] = speed * math.cos(a), speed * math.sin(a)
  end
  collectgarbage('collect')
  collectgarbage('collect')
  local before = collectgarbage('count')
  local t, out = Tree.new(), {}
  for i = 1, n do id[i] = t:insert(x[i], y[i], x[i] + w[i], y[i] + h[i]) end
  collectgarbage('collect')
  collectgarbage('collect')
  local kbPerProxy = (collectgarbage('count') - before) / n
  local moves = 0
  local function frame()
    for i = 1, n do
      local nx, ny = x[i] + vx[i], y[i] + vy[i]
      if nx < 0 or nx + w[i] > side then vx[i] = -vx[i] end
      if ny < 0 or ny + h[i] > side then vy[i] = -vy[i] end
      x[i], y[i] = nx, ny
      t:update(id[i], nx, ny, nx + w[i], ny + h[i])
    end
    return t:pairs(out)
  end
  local frames = math.max(10, math.floor(2e6 / n))
  for _ = 1, frames do frame() end -- warm-up
  local best, np = math.huge, 0
  for _ = 1, 3 do
    local t0 = clock()
    for _ = 1, frames do np = frame() end
    local dt = (clock() - t0) / frames
    if dt < best then best = dt end
  end
  -- the update phase alone, and the share of bodies leaving their fat boxes
  local tUpdate
  do
    local t0 = clock()
    for _ = 1, frames do
      for i = 1, n do
        local nx, ny = x[i] + vx[i], y[i] + vy[i]
        if nx < 0 or nx + w[i] > side then vx[i] = -vx[i] end
        if ny < 0 or ny + h[i] > side then vy[i] = -vy[i] end
        x[i], y[i] = nx, ny
        local j = id[i]
        local out0 = not (nx >= t.fx0[j] and ny >= t.fy0[j] and nx + w[i] <= t.fx1[j]
          and ny + h[i] <= t.fy1[j])
        if out0 then moves = moves + 1 end
        t:update(j, nx, ny, nx + w[i], ny + h[i])
      end
    end
    tUpdate = (clock() - t0) / frames
    t:pairs(out)
  end
  collectgarbage('collect')
  collectgarbage('stop')
  local g0 = collectgarbage('count')
  for _ = 1, frames do frame() end
  local kbPerFrame = (collectgarbage('count') - g0) / frames
  collectgarbage('restart')
  print(('N=%6d  %8.3f ms/frame (updates alone %7.3f)  pairs %6d  candidates %7d  refit %4.1f%%/frame  depth %2d'
    .. '  %.3f KB/proxy  %.4f KB/frame'):format(
    n, best * 1e3, tUpdate * 1e3, np, t:candidates(), 100 * moves / (n * frames), t:depth(),
    kbPerProxy, kbPerFrame))
end

print(('%s%s'):format(jit and jit.version or _VERSION, mixed and ', mixed sizes' or ''))
for _, n in ipairs(sizes) do measure(n) end
if jit then print(('trace flushes: %d'):format(flushes)) end
