-- The hierarchical grid broadphase (bench/broadphase/hgrid.lua): its pairs and queries against
-- a brute-force check over every pair, on seeded random worlds that grow, move (a little, and
-- by teleports), resize and shrink. Reproduce a failure with STRIKE_SEED=<seed> (any VM).
local HGrid = require('bench.broadphase.hgrid')
local PRNG = require('spec.helpers.prng')
local alloc = require('spec.helpers.alloc')

local SEED = PRNG.seedFromEnv(20261123)

-- The reference: boxes by id (false when removed), every pair tested.
local function brutePairs(boxes, maxId)
  local out, n = {}, 0
  for a = 1, maxId do
    local A = boxes[a]
    if A then
      for b = a + 1, maxId do
        local B = boxes[b]
        if B and B[1] <= A[3] and A[1] <= B[3] and B[2] <= A[4] and A[2] <= B[4] then
          out[2 * n + 1], out[2 * n + 2] = a, b
          n = n + 1
        end
      end
    end
  end
  return out, n
end

local function bruteQuery(boxes, maxId, x0, y0, x1, y1)
  local out = {}
  for id = 1, maxId do
    local B = boxes[id]
    if B and B[1] <= x1 and x0 <= B[3] and B[2] <= y1 and y0 <= B[4] then out[#out + 1] = id end
  end
  return out
end

local function same(got, n, want, m)
  if n ~= m then return false, ('%d results, expected %d'):format(n, m) end
  for i = 1, #want do
    if got[i] ~= want[i] then
      return false, ('entry %d is %s, expected %s'):format(i, tostring(got[i]), tostring(want[i]))
    end
  end
  if got[#want + 1] ~= nil then return false, 'entries left past the end' end
  return true
end

-- A random box: sizes from 0 to 2,000 (mostly small), somewhere in a square of side `side`
-- around (ox, oy).
local function randomBox(rng, ox, oy, side)
  local r = rng:next()
  local w, h
  if r < 0.1 then w, h = 0, 0
  elseif r < 0.2 then w, h = 1, 1
  elseif r < 0.25 then w, h = rng:range(0, 2000), rng:range(0, 40)
  elseif r < 0.3 then w, h = 0, rng:range(0, 300)
  else w, h = rng:range(1, 40), rng:range(1, 40) end
  local x, y = ox + rng:range(0, side), oy + rng:range(0, side)
  if rng:next() < 0.1 then x, y = ox + rng:int(0, 20) * 16, oy + rng:int(0, 20) * 16 end -- on cell lines
  return { x, y, x + w, y + h }
end

-- Run `rounds` rounds of random edits on a fresh grid, checking pairs and queries after each.
local function scenario(seed, ox, oy, side, rounds, maxBoxes)
  local rng = PRNG.new(seed)
  local bp = HGrid.new()
  local boxes, maxId, live = {}, 0, 0
  local out, qout = {}, {}
  local function check(round)
    local want, m = brutePairs(boxes, maxId)
    local n = bp:pairs(out)
    local ok, why = same(out, n, want, m)
    assert(ok, ('seed %d round %d: pairs: %s'):format(seed, round, tostring(why)))
    assert.are.equal(live, bp:count())
    for _ = 1, 3 do
      local q = randomBox(rng, ox, oy, side)
      if rng:next() < 0.2 then q[3], q[4] = q[1] + rng:range(0, side), q[2] + rng:range(0, side) end
      local k = bp:query(q[1], q[2], q[3], q[4], qout)
      local qw = bruteQuery(boxes, maxId, q[1], q[2], q[3], q[4])
      ok, why = same(qout, k, qw, #qw)
      assert(ok, ('seed %d round %d: query (%.17g, %.17g, %.17g, %.17g): %s'):format(seed, round, q[1], q[2], q[3],
        q[4], tostring(why)))
    end
  end
  for round = 1, rounds do
    -- inserts
    for _ = 1, rng:int(0, 12) do
      if live < maxBoxes then
        local b = randomBox(rng, ox, oy, side)
        local id = bp:insert(b[1], b[2], b[3], b[4])
        assert(not boxes[id], ('seed %d round %d: id %d given twice'):format(seed, round, id))
        boxes[id] = b
        if id > maxId then maxId = id end
        live = live + 1
      end
    end
    -- moves: most a little, some teleports, some resizes
    for id = 1, maxId do
      local b = boxes[id]
      if b then
        local r = rng:next()
        if r < 0.6 then
          local dx, dy = rng:range(-3, 3), rng:range(-3, 3)
          b[1], b[2], b[3], b[4] = b[1] + dx, b[2] + dy, b[3] + dx, b[4] + dy
          bp:update(id, b[1], b[2], b[3], b[4])
        elseif r < 0.7 then
          local nb = randomBox(rng, ox, oy, side)
          local dx, dy = nb[1] - b[1], nb[2] - b[2]
          b[1], b[2], b[3], b[4] = b[1] + dx, b[2] + dy, b[3] + dx, b[4] + dy
          bp:update(id, b[1], b[2], b[3], b[4])
        elseif r < 0.75 then
          boxes[id] = randomBox(rng, ox, oy, side)
          b = boxes[id]
          bp:update(id, b[1], b[2], b[3], b[4])
        end
      end
    end
    -- removes
    for _ = 1, rng:int(0, 8) do
      local id = rng:int(1, math.max(1, maxId))
      if boxes[id] then
        bp:remove(id)
        boxes[id] = false
        live = live - 1
      end
    end
    check(round)
  end
  return bp
end

describe('bench.broadphase.hgrid', function()
  it('finds exactly the overlapping pairs and query hits, in order, on random mixed-size worlds', function()
    for i = 0, 3 do
      scenario(SEED + i, 0, 0, 600, 40, 150)
    end
  end)

  it('works far from the origin (1e9), on both sides, and at a small scale', function()
    scenario(SEED + 10, 1e9, -1e9, 600, 25, 120)
    scenario(SEED + 11, -1e9 - 3.25, 1e9 + 0.5, 600, 25, 120)
    scenario(SEED + 12, -300, -300, 600, 25, 120) -- across the origin
  end)

  it('handles crowds in one cell and many levels at once', function()
    local bp = HGrid.new()
    for i = 1, 30 do bp:insert(5, 5, 5 + i % 7, 5 + i % 5) end -- all overlapping
    local out = {}
    assert.are.equal(30 * 29 / 2, bp:pairs(out))
    for s = 0, 12 do bp:insert(-2 ^ s, -2 ^ s, 0, 0) end -- one box on each level, nested
    local n = bp:pairs(out)
    assert.are.equal(30 * 29 / 2 + 13 * 12 / 2, n)
    assert.are.equal(1, out[1])
    assert.are.equal(2, out[2])
  end)

  it('counts touching boxes (closed intervals), and 0-size boxes', function()
    local bp = HGrid.new()
    local a = bp:insert(0, 0, 16, 16)
    local b = bp:insert(16, 0, 32, 16) -- touches a's right side
    local c = bp:insert(16, 16, 16, 16) -- a point on both corners
    local d = bp:insert(32.5, 0, 33, 1) -- apart
    local out = {}
    assert.are.equal(3, bp:pairs(out))
    assert.are.same({ a, b, a, c, b, c }, out)
    assert.are.equal(1, bp:query(33, 1, 40, 40, out))
    assert.are.same({ d }, out)
    assert.are.equal(0, bp:query(100, 100, 100, 100, out))
    assert.are.same({}, out)
  end)

  it('keeps moves, removes and reinserts made between two calls of pairs straight', function()
    local rng = PRNG.new(SEED + 40)
    local bp = HGrid.new()
    local boxes = {}
    for i = 1, 40 do
      boxes[i] = randomBox(rng, 0, 0, 200)
      bp:insert(boxes[i][1], boxes[i][2], boxes[i][3], boxes[i][4])
    end
    -- many cycles with no pairs or query in between: moves wait to be refiled, removed ids
    -- leave stale entries in that list, and ids come back
    for _ = 1, 400 do
      local id = rng:int(1, 40)
      local b = randomBox(rng, 0, 0, 200)
      bp:update(id, b[1], b[2], b[3], b[4])
      bp:remove(id)
      assert.are.equal(id, bp:insert(b[1], b[2], b[3], b[4]))
      b = randomBox(rng, 0, 0, 200)
      bp:update(id, b[1], b[2], b[3], b[4])
      boxes[id] = b
    end
    local want, m = brutePairs(boxes, 40)
    local out = {}
    local ok, why = same(out, bp:pairs(out), want, m)
    assert(ok, ('seed %d: %s'):format(SEED + 40, tostring(why)))
  end)

  it('reuses the most recently freed id first, else the next unused one', function()
    local bp = HGrid.new()
    for i = 1, 5 do assert.are.equal(i, bp:insert(i, i, i + 1, i + 1)) end
    bp:remove(2)
    bp:remove(4)
    assert.are.equal(3, bp:count())
    assert.are.equal(4, bp:insert(0, 0, 1, 1))
    assert.are.equal(2, bp:insert(0, 0, 1, 1))
    assert.are.equal(6, bp:insert(0, 0, 1, 1))
  end)

  it('refuses bad boxes and unknown ids at the caller', function()
    local bp = HGrid.new()
    local id = bp:insert(0, 0, 1, 1)
    assert.has_error(function() bp:insert(1, 0, 0, 1) end)
    assert.has_error(function() bp:insert(0, 0, 0 / 0, 1) end)
    assert.has_error(function() bp:insert(0, 0, math.huge, 1) end)
    assert.has_error(function() bp:update(id, 0, 0, -1, 1) end)
    assert.has_error(function() bp:update(99, 0, 0, 1, 1) end)
    bp:remove(id)
    assert.has_error(function() bp:remove(id) end)
    assert.has_error(function() bp:update(id, 0, 0, 1, 1) end)
  end)

  describe('allocation', function()
    setup(alloc.jitOff) -- measured interpreted on LuaJIT: see spec/helpers/alloc.lua
    teardown(alloc.jitOn)

    it('allocates nothing per frame in a steady state (moves, cell changes, pairs, queries)', function()
      local rng = PRNG.new(SEED + 30)
      local bp = HGrid.new()
      local n, side = 300, 40 * math.sqrt(300)
      local x, y, w, h, vx, vy = {}, {}, {}, {}, {}, {}
      for i = 1, n do
        x[i], y[i] = rng:range(0, side), rng:range(0, side)
        w[i], h[i] = rng:range(8, 28), rng:range(8, 28)
        if i % 50 == 0 then w[i] = 2000 elseif i % 10 == 0 then w[i], h[i] = 1, 1 end
        vx[i], vy[i] = rng:range(-2, 2), rng:range(-2, 2)
        bp:insert(x[i], y[i], x[i] + w[i], y[i] + h[i])
      end
      local out, qout = {}, {}
      local function frame()
        for i = 1, n do
          local nx, ny = x[i] + vx[i], y[i] + vy[i]
          if nx < 0 or nx > side then vx[i] = -vx[i] end
          if ny < 0 or ny > side then vy[i] = -vy[i] end
          x[i], y[i] = nx, ny
          bp:update(i, nx, ny, nx + w[i], ny + h[i])
        end
        bp:pairs(out)
        bp:query(100, 100, 300, 300, qout)
      end
      -- a frame moves every box, so 10,000 frames would be slow: windows of 100 frames (30,000
      -- moves, 100 pairs and 100 queries each), after 100 frames of warm-up
      local kb = alloc.kbPer(frame, 100, 100)
      alloc.nothingPerCall(kb, 'a frame of the hierarchical grid')
    end)
  end)
end)
