-- Allocation budget: with an `out` MTV, the collision paths allocate nothing.
-- This counts kilobytes (collectgarbage 'count' with the GC stopped), never seconds.
local S = require('strike')
local alloc = require('spec.helpers.alloc')
local kbPer, nothingPerCall, ONE_TIME_KB = alloc.kbPer, alloc.nothingPerCall, alloc.ONE_TIME_KB

describe('allocation', function()
  setup(alloc.jitOff) -- measured interpreted on LuaJIT: see spec/helpers/alloc.lua
  teardown(alloc.jitOn)
  local H, T = S.hapes, S.trikers
  local poly = H.Rectangle(0, 0, 10, 10, 0.3)
  local oct = H.RegularPolygon(5, 3, 8, 6)
  local circle = H.Circle(3, 3, 4)
  local edge = H.Edge(-5, 0, 10, 3)
  local out = S.MTV()

  it('S.AT with an out MTV allocates nothing, for every pair type', function()
    local pairsToTest = {
      { poly, oct }, { poly, circle }, { circle, oct }, { circle, H.Circle(4, 4, 2) }, { edge, poly }, { circle, edge },
      { poly, H.Rectangle(100, 0, 1) }, -- separating
    }
    for i, p in ipairs(pairsToTest) do
      local a, b = p[1], p[2]
      nothingPerCall(kbPer(function() S.AT(a, b, out) end, 10000), 'S.AT pair ' .. i)
    end
  end)

  it('S.triking with an out MTV allocates nothing, on single and compound colliders', function()
    local a, b = T.Rectangle(0, 0, 10, 10, 0.3), T.RegularPolygon(5, 3, 8, 6)
    nothingPerCall(kbPer(function() S.triking(a, b, out) end, 10000), 'S.triking, single shapes')
    local c1 = T.Collider(H.Rectangle(0, 0, 10), H.Circle(8, 0, 3), T.Collider(H.Edge(0, 5, 10, 5)))
    local c2 = T.Capsule(4, 4, 6, 20, 0.4)
    nothingPerCall(kbPer(function() S.triking(c1, c2, out) end, 10000), 'S.triking, compound')
    local far = T.Circle(500, 0, 1)
    nothingPerCall(kbPer(function() S.triking(c1, far, out) end, 10000), 'S.triking, apart')
  end)

  it('S.ite with an out table allocates nothing', function()
    local floor, box, ball = H.Rectangle(0, 5, 100, 10), H.Rectangle(0, -4.5, 4, 10, 0.1), H.Circle(3, -4, 5)
    local m1, m2, contacts = S.AT(floor, box), S.AT(floor, ball), {}
    nothingPerCall(kbPer(function() S.ite(m1, contacts) S.ite(m2, contacts) end, 10000), 'S.ite')
    -- compound MTVs: a box out of an L's inner corner (4 points), a ball between two boxes
    local L = T.Collider(H.Rectangle(50, 10, 100, 20), H.Rectangle(10, 50, 20, 100))
    local m3 = S.triking(L, H.Rectangle(22, 22, 10, 10))
    local m4 = S.triking(T.Collider(H.Rectangle(5, 5, 10, 10), H.Rectangle(23, 5, 10, 10)), H.Circle(14, 3, 5))
    nothingPerCall(kbPer(function() S.ite(m3, contacts) S.ite(m4, contacts) end, 10000), 'S.ite, compound')
  end)

  it('transforms, bounds and elems allocate nothing', function()
    local c = T.Collider(H.Rectangle(0, 0, 10), H.Circle(8, 0, 3))
    nothingPerCall(kbPer(function()
      c:translate(1, 0):rotate(0.01):scale(1.0001)
      c:getBbox()
      for s in c:elems() do s:getBbox() end
      poly:translate(0, 1):rotate(0.1)
      poly:getBbox()
    end, 10000), 'transforms')
  end)

  it('without out, S.AT and S.triking make exactly one result table per call', function()
    local last -- results are kept, so that no VM can optimise the allocation away
    local a, b = T.Rectangle(0, 0, 10, 10, 0.3), T.RegularPolygon(5, 3, 8, 6)
    local fresh = kbPer(function() last = S.AT(poly, oct) end, 1000)
    local oneFilled = kbPer(function() last = S.AT(poly, oct, S.MTV()) end, 1000)
    assert.is_true(fresh > 0)
    assert.is_true(math.abs(oneFilled - fresh) < ONE_TIME_KB, ('%g KB vs %g KB'):format(fresh, oneFilled))
    fresh = kbPer(function() last = S.triking(a, b) end, 1000)
    oneFilled = kbPer(function() last = S.triking(a, b, S.MTV()) end, 1000)
    assert.is_true(math.abs(oneFilled - fresh) < ONE_TIME_KB, ('%g KB vs %g KB'):format(fresh, oneFilled))
    assert.is_table(last)
  end)
end)
