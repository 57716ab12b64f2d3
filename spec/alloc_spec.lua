-- Allocation budget: with an `out` MTV, the collision paths allocate nothing.
-- This counts kilobytes (collectgarbage 'count' with the GC stopped), never seconds.
local S = require('strike')
-- Locals, not globals: busted runs specs in an environment whose global lookups may
-- allocate, and the measuring window must hold only the calls being measured.
local collectgarbage, huge = collectgarbage, math.huge

local function run(fn, n)
  for _ = 1, n do fn() end
end

-- KB allocated by `n` calls of `fn`: the least of three windows, each with the GC stopped
-- and after a warm-up through the same loop.
local function kbPer(fn, n)
  run(fn, 20000)
  local least = huge
  for _ = 1, 3 do
    collectgarbage('collect')
    collectgarbage('stop')
    run(fn, 100)
    local before = collectgarbage('count')
    run(fn, n)
    local used = collectgarbage('count') - before
    collectgarbage('restart')
    if used < least then least = used end
  end
  return least
end

-- "Allocates nothing" means no allocation per call. The smallest Lua allocation is 16
-- bytes or more, so one per call over 10,000 calls is at least 156 KB. A window may still
-- hold a one-time growth of the VM's own: under busted, Lua 5.2 shows the same ~3.2 KB
-- whether the window holds 1 call or 40,000, so the budget is under 4 KB per window.
local ONE_TIME_KB = 4
local function nothingPerCall(kb, what)
  assert(kb < ONE_TIME_KB, ('%s allocated %.3f KB over 10,000 calls'):format(what, kb))
end

-- On LuaJIT the measurements run interpreted: the trace compiler allocates its own
-- bookkeeping whenever it compiles a new side trace, which can happen at any moment, while
-- the interpreter shows the program's allocations exactly (compiled code can only sink
-- allocations, never add any). bench/ reports garbage with the JIT on.
local jit = rawget(_G, 'jit')

describe('allocation', function()
  setup(function() if jit then jit.off() end end)
  teardown(function() if jit then jit.on() end end)
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
