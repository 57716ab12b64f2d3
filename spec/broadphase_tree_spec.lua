-- The dynamic AABB tree broadphase (bench/broadphase/tree.lua), checked against a brute-force
-- O(n^2) oracle on seeded random worlds: inserts, small moves, teleports and removes, mixed
-- sizes (points, 1 px, 2,000 px), near the origin and at 1e9. STRIKE_SEED picks the seed.
local Tree = require('strike.space.tree')
local PRNG = require('spec.helpers.prng')
local alloc = require('spec.helpers.alloc')

local SEED = PRNG.seedFromEnv(20240611)

-- The oracle: live[id] = true and the boxes, kept beside the tree.
local function newOracle()
  return { live = {}, x0 = {}, y0 = {}, x1 = {}, y1 = {}, top = 0 }
end

local function oracleSet(o, id, x0, y0, x1, y1)
  o.live[id], o.x0[id], o.y0[id], o.x1[id], o.y1[id] = true, x0, y0, x1, y1
  if id > o.top then o.top = id end
end

local function overlaps(o, a, x0, y0, x1, y1)
  return o.x0[a] <= x1 and o.x1[a] >= x0 and o.y0[a] <= y1 and o.y1[a] >= y0
end

local function oraclePairs(o)
  local out = {}
  for a = 1, o.top do
    if o.live[a] then
      for b = a + 1, o.top do
        if o.live[b] and overlaps(o, b, o.x0[a], o.y0[a], o.x1[a], o.y1[a]) then
          out[#out + 1] = a
          out[#out + 1] = b
        end
      end
    end
  end
  return out
end

local function oracleQuery(o, x0, y0, x1, y1)
  local out = {}
  for a = 1, o.top do
    if o.live[a] and overlaps(o, a, x0, y0, x1, y1) then out[#out + 1] = a end
  end
  return out
end

-- got[1..#got] (n results of `per` entries each) equals want.
local function sameList(got, n, per, want, what, seed)
  local msg = ('%s (seed %d: STRIKE_SEED=%d reproduces)'):format(what, seed, seed)
  if n * per ~= #want or #got ~= #want then
    error(('%s: %d results in %d entries, want %d entries'):format(msg, n, #got, #want), 2)
  end
  for i = 1, #want do
    if got[i] ~= want[i] then
      error(('%s: entry %d is %s, want %s'):format(msg, i, tostring(got[i]), tostring(want[i])), 2)
    end
  end
end

-- A random box: mostly 8-28 px, some points, 1 px bullets, segments and 2,000 px platforms.
local function randomBox(rng, cx, cy, side)
  if side < 0 then -- integer corners and sizes 0-3 on a small grid: boxes touch often
    local x, y = cx + rng:int(0, -side), cy + rng:int(0, -side)
    return x, y, x + rng:int(0, 3), y + rng:int(0, 3)
  end
  local x, y = cx + rng:range(0, side), cy + rng:range(0, side)
  local kind = rng:int(1, 10)
  local w, h
  if kind == 1 then
    w, h = 0, 0
  elseif kind == 2 then
    w, h = 1, 1
  elseif kind == 3 then
    w, h = rng:range(500, 2000), rng:range(0, 30)
  elseif kind == 4 then
    w, h = 0, rng:range(0, 60)
  else
    w, h = rng:range(8, 28), rng:range(8, 28)
  end
  return x, y, x + w, y + h
end

-- Where the ray (x, y) + t (ux, uy) enters box a within [0, maxT], by the slab test without
-- the tree's padding; nil when it misses.
local function oracleEntry(o, a, x, y, ux, uy, maxT)
  local lo, hi = 0, maxT
  for axis = 1, 2 do
    local p, u, b0, b1 = x, ux, o.x0[a], o.x1[a]
    if axis == 2 then p, u, b0, b1 = y, uy, o.y0[a], o.y1[a] end
    local inv = 1 / u
    if inv == math.huge or inv == -math.huge then
      if p < b0 or p > b1 then return nil end
    else
      local t1, t2 = (b0 - p) * inv, (b1 - p) * inv
      if t1 > t2 then t1, t2 = t2, t1 end
      if t1 > lo then lo = t1 end
      if t2 < hi then hi = t2 end
    end
  end
  if lo <= hi then return lo end
  return nil
end

-- A random ray against the tree: rayCandidates gives every box the oracle's ray enters, and
-- rayVisit, whose visitor takes every third box's entry as a hit, visits every box entered
-- before the best hit it ends with, which is the oracle's nearest such entry or nearer (the
-- tree pads boxes by a rounding's worth).
local function checkRay(tree, o, rng, cx, cy, side, seed)
  local span = math.abs(side)
  local x, y = cx + rng:range(-0.1, 1.1) * span, cy + rng:range(-0.1, 1.1) * span
  local a = rng:range(-math.pi, math.pi)
  local ux, uy = math.cos(a), math.sin(a)
  if rng:int(1, 8) == 1 then ux, uy = 0, (rng:int(0, 1) * 2 - 1) end -- along an axis
  local maxT = rng:range(0, 1.5) * span
  local msg = ('ray from %s, %s along %s, %s (seed %d: STRIKE_SEED=%d reproduces)'):format(x, y, ux, uy, seed, seed)
  local ids, ts = {}, {}
  local k = tree:rayCandidates(x, y, ux, uy, maxT, ids, ts)
  local found = {}
  for i = 1, k do found[ids[i]] = true end
  local visited, best = {}, maxT
  tree:rayVisit(x, y, ux, uy, maxT, function(ctx, id, t, limit)
    assert(ctx == o, msg .. ': the context')
    assert(o.live[id] and not visited[id], msg .. ': a proxy visited twice, or not in the tree')
    assert(t <= limit and limit == best, msg .. ': a box beyond the best hit so far')
    visited[id] = true
    if id % 3 == 0 and t < best then best = t end
    return best
  end, o)
  local nearest = maxT
  for id = 1, o.top do
    if o.live[id] then
      local t = oracleEntry(o, id, x, y, ux, uy, maxT)
      if t then
        assert(found[id], msg .. (': rayCandidates missed box %d, entered at %s'):format(id, t))
        if t < best then assert(visited[id], msg .. (': rayVisit missed box %d, entered at %s'):format(id, t)) end
        if id % 3 == 0 and t < nearest then nearest = t end
      end
    end
  end
  assert(best <= nearest, msg .. (': the best hit %s, the oracle\'s %s'):format(best, nearest))
end

-- Run a random world: `rounds` rounds of inserts, moves and removes, checking pairs after each
-- and a few queries and rays. Returns the tree's height at the end. With `bursts`, round r
-- inserts bursts[r] boxes (when given) instead of 0-30: many at once build the tree of
-- resting boxes again in bulk.
local function run(seed, cx, cy, side, rounds, bursts)
  local rng = PRNG.new(seed)
  local tree, o = Tree.new(), newOracle()
  local ids, out = {}, {}
  local maxDepth = 0
  for round = 1, rounds do
    for _ = 1, bursts and bursts[round] or rng:int(0, 30) do
      local x0, y0, x1, y1 = randomBox(rng, cx, cy, side)
      local id = tree:insert(x0, y0, x1, y1)
      assert(not o.live[id], 'a live id was given out again')
      oracleSet(o, id, x0, y0, x1, y1)
      ids[#ids + 1] = id
    end
    for k = 1, #ids do
      local id = ids[k]
      local r = rng:next()
      if r < 0.7 then -- small move
        local dx, dy = rng:range(-3, 3), rng:range(-3, 3)
        if side < 0 then dx, dy = rng:int(-1, 1), rng:int(-1, 1) end
        local x0, y0, x1, y1 = o.x0[id] + dx, o.y0[id] + dy, o.x1[id] + dx, o.y1[id] + dy
        tree:update(id, x0, y0, x1, y1)
        oracleSet(o, id, x0, y0, x1, y1)
      elseif r < 0.75 then -- teleport, and a new size
        local x0, y0, x1, y1 = randomBox(rng, cx, cy, side)
        tree:update(id, x0, y0, x1, y1)
        oracleSet(o, id, x0, y0, x1, y1)
      end -- else: stays where it is
    end
    for _ = 1, rng:int(0, 20) do
      if #ids > 0 then
        local k = rng:int(1, #ids)
        local id = ids[k]
        ids[k] = ids[#ids]
        ids[#ids] = nil
        tree:remove(id)
        o.live[id] = nil
      end
    end
    assert.are.equal(#ids, tree:count())
    do -- a query before pairs: the moves reach the tree first
      local x0, y0, x1, y1 = randomBox(rng, cx, cy, side)
      local k = tree:query(x0, y0, x1, y1, out)
      sameList(out, k, 1, oracleQuery(o, x0, y0, x1, y1), 'query before pairs', seed)
    end
    local n = tree:pairs(out)
    sameList(out, n, 2, oraclePairs(o), 'pairs', seed)
    for _ = 1, 3 do
      local x0, y0, x1, y1 = randomBox(rng, cx, cy, side)
      local k = tree:query(x0, y0, x1, y1, out)
      sameList(out, k, 1, oracleQuery(o, x0, y0, x1, y1), 'query', seed)
    end
    for _ = 1, 4 do checkRay(tree, o, rng, cx, cy, side, seed) end
    if tree:depth() > maxDepth then maxDepth = tree:depth() end
  end
  return tree, #ids, maxDepth
end

describe('bench.broadphase.tree', function()
  it('gives ids from 1 and reuses the last freed id first', function()
    local t = Tree.new()
    for i = 1, 6 do assert.are.equal(i, t:insert(i, 0, i + 1, 1)) end
    t:remove(5)
    t:remove(2)
    t:remove(4)
    assert.are.equal(3, t:count())
    assert.are.equal(4, t:insert(0, 0, 1, 1))
    assert.are.equal(2, t:insert(0, 0, 1, 1))
    assert.are.equal(5, t:insert(0, 0, 1, 1))
    assert.are.equal(7, t:insert(0, 0, 1, 1))
    assert.are.equal(7, t:count())
  end)

  it('counts touching boxes (closed intervals), points and segments included', function()
    local t, out = Tree.new(), {}
    t:insert(0, 0, 10, 10) -- 1
    t:insert(10, 10, 20, 20) -- 2: touches 1 at a corner
    t:insert(5, 5, 5, 5) -- 3: a point inside 1
    t:insert(20, 0, 20, 30) -- 4: a segment along 2's right side
    t:insert(30, 30, 30, 30) -- 5: a point, alone
    out[7], out[8], out[9] = 0, 0, 0 -- (stale entries: cleared)
    assert.are.equal(3, t:pairs(out))
    assert.are.same({ 1, 2, 1, 3, 2, 4 }, out)
    assert.are.equal(3, t:query(20, 20, 40, 40, out))
    assert.are.same({ 2, 4, 5 }, out)
    assert.are.equal(0, t:query(100, 100, 101, 101, out))
    assert.are.same({}, out)
  end)

  it('pairs points that meet, however they got there', function()
    local t, out = Tree.new(), {}
    t:insert(7, 7, 7, 7)
    t:insert(7, 7, 7, 7) -- inserted onto the first
    assert.are.equal(1, t:pairs(out))
    t:update(2, 8, 8, 8, 8)
    assert.are.equal(0, t:pairs(out))
    t:update(2, 7, 7, 7, 7) -- moved back onto it
    assert.are.equal(1, t:pairs(out))
    t:update(1, 9, 9, 9, 9)
    t:update(2, 9, 9, 9, 9) -- both moved, onto the same spot
    assert.are.equal(1, t:pairs(out))
    assert.are.same({ 1, 2 }, out)
    t:insert(9, 9, 12, 9) -- a segment starting there
    assert.are.equal(3, t:pairs(out))
    assert.are.same({ 1, 2, 1, 3, 2, 3 }, out)
  end)

  it('says which call was wrong', function()
    local t = Tree.new()
    local id = t:insert(0, 0, 1, 1)
    assert.has_error(function() t:insert(1, 0, 0, 1) end)
    assert.has_error(function() t:update(id, 0, 0 / 0, 1, 1) end)
    t:remove(id)
    assert.has_error(function() t:update(id, 0, 0, 1, 1) end,
      'tree.update: expected the id of a proxy in this tree, got 1')
    assert.has_error(function() t:remove(id) end)
  end)

  it('matches brute force on random worlds near the origin', function()
    for s = 0, 3 do
      local _, n, depth = run(SEED + s, -400, -300, 800, 25)
      local bound = 3 * math.log(n + 2) / math.log(2) + 2
      assert(depth <= bound, ('tree too deep: %d for %d (seed %d)'):format(depth, n, SEED + s))
    end
  end)

  it('matches brute force when many boxes arrive at once (the tree built again in bulk)', function()
    -- (400 into an empty tree; 300 into one of about 400 resting boxes, some moved away; 255
    -- and 256, below and at the threshold, into one of about 950)
    run(SEED + 40, -400, -300, 800, 6, { 400, 0, 300, 0, 255, 256 })
    run(SEED + 41, 0, 0, -40, 4, { 300, 5, 280, 0 })
  end)

  it('builds the tree of resting boxes balanced, split at the median, when many arrive at once', function()
    local t = Tree.new()
    for i = 1, 1024 do t:insert(i * 10, 0, i * 10 + 5, 5) end
    local out = {}
    assert.are.equal(2, t:query(5000, 0, 5010, 5, out))
    assert.are.same({ 500, 501 }, out)
    assert.are.equal(1, t:rebuilds())
    assert.are.equal(10, t:depth())
    local halves = {}
    t:eachNode(function(_, x0, _, x1, _, depth)
      if depth == 1 then halves[#halves + 1] = { x0, x1 } end
    end)
    table.sort(halves, function(a, b) return a[1] < b[1] end)
    assert.are.same({ { 10, 5125 }, { 5130, 10245 } }, halves) -- (512 boxes each side)
    -- a column in shuffled order: split along y, the 500 lowest boxes on one side
    local c, rng, order = Tree.new(), PRNG.new(SEED + 42), {}
    for i = 1, 1000 do order[i] = i end
    for i = 1000, 2, -1 do
      local j = rng:int(1, i)
      order[i], order[j] = order[j], order[i]
    end
    for i = 1, 1000 do c:insert(3, order[i] * 10, 8, order[i] * 10 + 5) end
    local ys = {}
    c:eachNode(function(_, _, y0, _, y1, depth)
      if depth == 1 then ys[#ys + 1] = { y0, y1 } end
    end)
    table.sort(ys, function(a, b) return a[1] < b[1] end)
    assert.are.same({ { 10, 5005 }, { 5010, 10005 } }, ys, 'seed ' .. SEED + 42)
    -- built again: its inner nodes reused, none lost
    for i = 1, 1024 do t:insert(i * 10, 20, i * 10 + 5, 25) end
    t:query(0, 0, 1, 1, out)
    assert.are.equal(2, t:rebuilds())
    assert.are.equal(2048 + 2047, t.nodeTop)
  end)

  it('builds in bulk from BULK new boxes, and only when they are at least half as many as the resting ones', function()
    local t, out = Tree.new(), {}
    local function add(n)
      for _ = 1, n do t:insert(0, 0, 1, 1) end
      t:query(0, 0, 1, 1, out)
    end
    add(255)
    assert.are.equal(0, t:rebuilds()) -- (one by one)
    t = Tree.new()
    add(256)
    assert.are.equal(1, t:rebuilds())
    add(300) -- (556 resting)
    assert.are.equal(2, t:rebuilds())
    add(277) -- 554 < 556
    assert.are.equal(2, t:rebuilds())
    t:remove(1)
    t:remove(2)
    t:update(3, 5, 5, 6, 6) -- (to the tree of moving boxes: 830 resting)
    add(414) -- 828 < 830
    assert.are.equal(2, t:rebuilds())
    t:remove(4)
    t:remove(5)
    add(621) -- 1,242 >= 1,242
    assert.are.equal(3, t:rebuilds())
  end)

  it('lets go of the lists a bulk build filled (as long as the level), and keeps them otherwise', function()
    -- (stale: the proxies awaiting flush; moved: the move buffer, until pairs)
    local t, out = Tree.new(), {}
    for i = 1, 300 do t:insert(i * 10, 0, i * 10 + 4, 4) end
    assert.are.equal(300, #t.stale)
    t:query(0, 0, 1, 1, out)
    assert.are.equal(1, t:rebuilds())
    assert.are.equal(0, #t.stale) -- (a new, empty list)
    assert.are.equal(300, #t.moved) -- (pairs needs it still)
    assert.are.equal(0, t:pairs(out))
    assert.are.equal(0, #t.moved)
    -- a flush and pairs without a bulk build keep their lists (no garbage frame after frame)
    local stale, moved = t.stale, t.moved
    for i = 1, 300 do t:update(i, i * 10, 50, i * 10 + 4, 54) end
    assert.are.equal(0, t:pairs(out))
    assert.are.equal(1, t:rebuilds())
    assert.are.equal(stale, t.stale)
    assert.are.equal(moved, t.moved)
    assert.are.equal(300, #t.stale) -- (its entries stay until overwritten)
  end)

  it('matches brute force on a dense world (most boxes overlap)', function()
    run(SEED + 10, 0, 0, 60, 15)
  end)

  it('matches brute force where boxes touch (integer corners, points and segments)', function()
    run(SEED + 15, 0, 0, -30, 15)
    run(SEED + 16, 1e9, 1e9, -30, 10)
  end)

  it('matches brute force far from the origin (1e9)', function()
    run(SEED + 20, 1e9, -1e9, 800, 20)
  end)

  it('keeps the proxies that never moved in a tree of their own, with their exact boxes', function()
    -- (a wall's fat box, grown for moves it never makes, made every query near it walk its
    -- ancestors; and small movers inserted among large resting boxes spoil both: bench/movers.lua)
    local t = Tree.new()
    for i = 1, 64 do t:insert(i * 10, 0, i * 10 + 4, 4) end -- resting: 1 .. 64
    for i = 1, 8 do t:insert(i * 10, 100, i * 10 + 4, 104) end -- 65 .. 72: to be moved
    for i = 69, 72 do t:update(i, (i - 64) * 10 + 1, 100, (i - 64) * 10 + 5, 104) end -- (before any query)
    t:query(0, 0, 1, 1, {})
    for i = 65, 68 do t:update(i, (i - 64) * 10 + 1, 100, (i - 64) * 10 + 5, 104) end -- (after one)
    t:update(3, 30, 0, 34, 4) -- "moved" to where it was: still resting
    local leaves = {}
    t:eachNode(function(_, x0, y0, x1, y1, _, leaf, moving)
      if leaf then leaves[#leaves + 1] = { x0, y0, x1, y1, moving } end
    end)
    assert.are.equal(72, #leaves)
    local resting, movers = 0, 0
    for _, l in ipairs(leaves) do
      if l[2] == 0 then -- a resting one: its leaf box is its exact box
        resting = resting + 1
        assert.is_false(l[5])
        assert.are.same({ l[1], 0, l[1] + 4, 4 }, { l[1], l[2], l[3], l[4] })
        assert.are.equal(0, l[1] % 10)
      else -- a moved one: a fat box, strictly around its exact box
        movers = movers + 1
        assert.is_true(l[5])
        assert(l[2] < 100 and l[4] > 104, 'a moved proxy keeps a fat box')
      end
    end
    assert.are.equal(64, resting)
    assert.are.equal(8, movers)
    -- the height is the taller tree's, whichever it is
    local depth = t:depth()
    assert(depth >= 6, 'depth ' .. depth .. ' for 64 resting proxies')
    for i = 1, 64 do t:remove(i) end
    assert(t:depth() >= 3, "depth " .. t:depth() .. " for 8 moved proxies") -- (at least 3 levels)
    local out = {}
    assert.are.equal(8, t:query(0, 0, 1000, 1000, out))
  end)

  it('stays shallow under churn (AVL-like rotations)', function()
    local t, rng, ids = Tree.new(), PRNG.new(SEED + 30), {}
    for i = 1, 1024 do -- sorted inserts: the worst case without rebalancing
      ids[i] = t:insert(i * 10, 0, i * 10 + 5, 5)
    end
    assert(t:depth() <= 15, 'depth ' .. t:depth() .. ' after 1,024 sorted inserts')
    for _ = 1, 2000 do
      local k = rng:int(1, #ids)
      t:remove(ids[k])
      local x = rng:range(0, 10000)
      ids[k] = t:insert(x, 0, x + 5, 5)
    end
    assert(t:depth() <= 15, 'depth ' .. t:depth() .. ' after churn')
  end)

  describe('allocation', function()
    setup(alloc.jitOff) -- measured interpreted on LuaJIT: see spec/helpers/alloc.lua
    teardown(alloc.jitOn)

    it('allocates nothing per frame (update every body, then pairs) in steady state', function()
      local rng, t, out = PRNG.new(SEED + 40), Tree.new(), {}
      local n, side = 300, 40 * math.sqrt(300)
      local x, y, w, h, vx, vy, id = {}, {}, {}, {}, {}, {}, {}
      for i = 1, n do
        w[i], h[i] = rng:range(8, 28), rng:range(8, 28)
        x[i], y[i] = rng:range(0, side - w[i]), rng:range(0, side - h[i])
        local a, v = rng:range(0, 2 * math.pi), rng:range(0.5, 2)
        vx[i], vy[i] = v * math.cos(a), v * math.sin(a)
        id[i] = t:insert(x[i], y[i], x[i] + w[i], y[i] + h[i])
      end
      local function frame()
        for i = 1, n do
          local nx, ny = x[i] + vx[i], y[i] + vy[i]
          if nx < 0 or nx + w[i] > side then vx[i] = -vx[i] end
          if ny < 0 or ny + h[i] > side then vy[i] = -vy[i] end
          x[i], y[i] = nx, ny
          t:update(id[i], nx, ny, nx + w[i], ny + h[i])
        end
        t:pairs(out)
      end
      alloc.nothingPerCall(alloc.kbPer(frame, 200, 1000), 'a frame of 300 bodies')
    end)
  end)
end)
