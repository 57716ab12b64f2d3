--- The broadphase candidates for S.pace (bench/broadphase/*.lua), side by side on the same
--- moving worlds: milliseconds per frame (update every moving body's bounds, then find every
--- overlapping pair), KB per proxy, KB allocated per frame, and whether the pairs are exactly
--- the overlapping ones (checked against a sort-and-sweep on x written here, on the first and
--- last timed frames). Not part of make test. From the repository root:
---   luajit bench/broadphase.lua [--n 1000,5000,20000] [--worlds uniform,clustered,mixed]
---                               [--frames 60] [--only tree]
--- Worlds (seeded, identical on every VM):
---   uniform    the issue's mix: a third boxes 8-24 px, a third polygons of circumradius
---              5-14 (bounds 2R), a third circles of radius 4-12, in a square of side
---              40 sqrt(N), each moving 0.5-2 px a frame and bouncing off the border;
---   clustered  the same bodies in N / 250 clusters (normal spread: the square's side / 40);
---   mixed      the uniform mix, with 1 % static platforms 200-2,000 px long and 20 px thick
---              and 10 % bullets of 1 px moving 8-20 px a frame.
package.path = './?.lua;./?/init.lua;' .. package.path
local PRNG = require('spec.helpers.prng')

local sqrt, cos, sin, pi, floor = math.sqrt, math.cos, math.sin, math.pi, math.floor
local clock = os.clock

local opts = { n = { 1000, 5000, 20000 }, worlds = { 'uniform', 'clustered', 'mixed' }, frames = 60,
  only = nil }
do
  local i = 1
  local list = require('bench.harness').list
  while arg[i] do
    local a, v = arg[i], arg[i + 1]
    if a == '--n' then opts.n = list(v)
    elseif a == '--worlds' then opts.worlds = list(v)
    elseif a == '--frames' then opts.frames = tonumber(v)
    elseif a == '--only' then opts.only = v
    else error('unknown option ' .. a) end
    i = i + 2
  end
end

local CANDIDATES = { 'sap', 'tree', 'hgrid' }

-- A world: flat arrays of body half-sizes, positions and velocities, and the square's side.
local function world(kind, n, seed)
  local rng = PRNG.new(seed)
  local side = 40 * sqrt(n)
  local w = { n = n, side = side, x = {}, y = {}, hw = {}, hh = {}, vx = {}, vy = {} }
  local clusters = {}
  if kind == 'clustered' then
    for c = 1, math.max(1, floor(n / 250)) do clusters[c] = { rng:range(0, side), rng:range(0, side) } end
  end
  for i = 1, n do
    local hw, hh
    local k = i % 3
    if k == 0 then hw, hh = rng:range(4, 12), rng:range(4, 12)
    elseif k == 1 then local r = rng:range(5, 14); hw, hh = r, r
    else local r = rng:range(4, 12); hw, hh = r, r end
    local speed, a = rng:range(0.5, 2), rng:range(-pi, pi)
    local x, y = rng:range(0, side), rng:range(0, side)
    if kind == 'clustered' then
      local c = clusters[rng:int(1, #clusters)]
      -- (a normal spread by Box-Muller, clamped into the square)
      local u1, u2 = rng:next(), rng:next()
      local rad = sqrt(-2 * math.log(u1)) * side / 40
      x = math.min(side, math.max(0, c[1] + rad * cos(2 * pi * u2)))
      y = math.min(side, math.max(0, c[2] + rad * sin(2 * pi * u2)))
    elseif kind == 'mixed' then
      if i % 100 == 0 then -- a static platform
        hw, hh, speed = rng:range(100, 1000), 10, 0
        if rng:next() < 0.5 then hw, hh = hh, hw end
      elseif i % 10 == 0 then -- a bullet
        hw, hh, speed = 0.5, 0.5, rng:range(8, 20)
      end
    end
    w.x[i], w.y[i], w.hw[i], w.hh[i] = x, y, hw, hh
    w.vx[i], w.vy[i] = speed * cos(a), speed * sin(a)
  end
  return w
end

-- One step of every moving body (bouncing off the square's border).
local function step(w)
  local x, y, vx, vy, side = w.x, w.y, w.vx, w.vy, w.side
  for i = 1, w.n do
    local dx, dy = vx[i], vy[i]
    if dx ~= 0 or dy ~= 0 then
      local nx, ny = x[i] + dx, y[i] + dy
      if nx < 0 or nx > side then vx[i] = -dx; nx = x[i] - dx end
      if ny < 0 or ny > side then vy[i] = -dy; ny = y[i] - dy end
      x[i], y[i] = nx, ny
    end
  end
end

-- The overlapping pairs of the world's boxes by sort and sweep on x, independent of the
-- candidates: a sorted list of keys a * 2^26 + b (a < b, body numbers).
local function brutePairs(w)
  local n, order = w.n, {}
  for i = 1, n do order[i] = i end
  local x, hw = w.x, w.hw
  table.sort(order, function(a, b) return x[a] - hw[a] < x[b] - hw[b] end)
  local keys = {}
  for p = 1, n do
    local a = order[p]
    local ax1, ay0, ay1 = x[a] + hw[a], w.y[a] - w.hh[a], w.y[a] + w.hh[a]
    for q = p + 1, n do
      local b = order[q]
      if x[b] - hw[b] > ax1 then break end
      if w.y[b] - w.hh[b] <= ay1 and w.y[b] + w.hh[b] >= ay0 then
        local lo, hi = a < b and a or b, a < b and b or a
        keys[#keys + 1] = lo * 67108864 + hi
      end
    end
  end
  table.sort(keys)
  return keys
end

-- Do the candidate's pairs (flat list, count, proxy id -> body) equal the brute force's?
local function samePairs(out, count, bodyOf, keys)
  if count ~= #keys then return false, ('%d pairs, expected %d'):format(count, #keys) end
  local got = {}
  for k = 1, count do
    local a, b = bodyOf[out[2 * k - 1]], bodyOf[out[2 * k]]
    if a > b then a, b = b, a end
    got[k] = a * 67108864 + b
  end
  table.sort(got)
  for k = 1, count do
    if got[k] ~= keys[k] then return false, ('pair %d differs'):format(k) end
  end
  return true
end

local function run(name, kind, n)
  -- (the tree won: it is S.pace's broadphase now, strike/space/tree.lua)
  local ok, Candidate = pcall(require, name == 'tree' and 'strike.space.tree' or 'bench.broadphase.' .. name)
  if not ok then return nil, 'not found' end
  local w = world(kind, n, 20261123 + n)
  collectgarbage()
  collectgarbage()
  local before = collectgarbage('count')
  local bp = Candidate.new()
  local ids, bodyOf = {}, {}
  local x, y, hw, hh = w.x, w.y, w.hw, w.hh
  local t0 = clock()
  for i = 1, n do
    local id = bp:insert(x[i] - hw[i], y[i] - hh[i], x[i] + hw[i], y[i] + hh[i])
    ids[i], bodyOf[id] = id, i
  end
  local buildMs = (clock() - t0) * 1000
  collectgarbage()
  collectgarbage()
  local kbPerProxy = (collectgarbage('count') - before) * 1024 / n -- (bytes, with the id lists)
  local out = {}
  local vx, vy = w.vx, w.vy
  local function frame()
    step(w)
    for i = 1, n do
      if vx[i] ~= 0 or vy[i] ~= 0 then bp:update(ids[i], x[i] - hw[i], y[i] - hh[i], x[i] + hw[i], y[i] + hh[i]) end
    end
    return bp:pairs(out)
  end
  for _ = 1, 10 do frame() end -- (warm up: tables grown, traces compiled)
  local count = frame()
  local okPairs, why = samePairs(out, count, bodyOf, brutePairs(w))
  collectgarbage()
  collectgarbage('stop')
  local kb0 = collectgarbage('count')
  t0 = clock()
  local frames = opts.frames
  for _ = 1, frames do count = frame() end
  local ms = (clock() - t0) * 1000 / frames
  local kbFrame = (collectgarbage('count') - kb0) / frames
  collectgarbage('restart')
  if okPairs then okPairs, why = samePairs(out, count, bodyOf, brutePairs(w)) end
  return { ms = ms, build = buildMs, bytes = kbPerProxy, kbFrame = kbFrame, pairs = count,
    ok = okPairs, why = why }
end

local jit = rawget(_G, 'jit')
io.stdout:write(('%s\n\n'):format(jit and jit.version or _VERSION))
io.stdout:write('| world | N | candidate | ms/frame | pairs | build ms | bytes/proxy | KB/frame | exact |\n')
io.stdout:write('|---|---|---|---|---|---|---|---|---|\n')
for _, kind in ipairs(opts.worlds) do
  for _, n in ipairs(opts.n) do
    for _, name in ipairs(CANDIDATES) do
      if not opts.only or opts.only == name then
        local r, err = run(name, kind, n)
        if r then
          io.stdout:write(('| %s | %d | %s | %.2f | %d | %.1f | %.0f | %.3f | %s |\n'):format(kind, n, name, r.ms,
            r.pairs, r.build, r.bytes, r.kbFrame, r.ok and 'yes' or ('NO: ' .. tostring(r.why))))
        else
          io.stdout:write(('| %s | %d | %s | — | — | — | — | — | %s |\n'):format(kind, n, name, err))
        end
        io.stdout:flush()
      end
    end
  end
end
