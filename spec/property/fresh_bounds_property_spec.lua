-- A body added to a space gets its box from its shapes' bounds alone: a polygon never
-- refreshed has them worked out without its vertex records (VertexShape:_freshBounds), which
-- wait, the shape staying dirty, for the first reader that needs them. The box must be the
-- very box a refresh gives, bit for bit, for every kind, pose, scale and rounding, bare or in
-- a collider; and the vertices then read must be a refresh's. Reproduce a failure with
-- STRIKE_SEED=<seed>.
local S = require('strike')
local PRNG = require('spec.helpers.prng')
local budget = require('spec.helpers.budget')
local layout = require('strike.base.layout')

local H, T = S.hapes, S.trikers
local SEED = PRNG.seedFromEnv(20270311)
local DIRTY = layout.DIRTY

local function show(v) return ('%.17g'):format(v) end

-- A random shape of a random kind, pose and size, somewhere from the origin to far from it.
local function randomShape(rng)
  local far = 10 ^ rng:range(0, 7)
  local x, y = rng:range(-far, far), rng:range(-far, far)
  local size = rng:range(0.5, 40)
  local angle = rng:next() < 0.3 and 0 or rng:range(-7, 7)
  local kind = rng:int(1, 7)
  if kind == 1 then return H.Rectangle(x, y, size, rng:range(0.5, 40), angle) end
  if kind == 2 then return H.Rectangle(x, y, size + 4, size + 2, angle, rng:range(0.1, 1.9)) end -- rounded
  if kind == 3 then return H.RegularPolygon(x, y, rng:int(3, 12), size, angle) end
  if kind == 4 then return H.Edge(x, y, x + rng:range(-size, size), y + rng:range(-size, size)) end
  if kind == 5 then return H.Capsule(x, y, size, size + rng:range(0, 30), angle) end
  if kind == 6 then return H.Ellipse(x, y, size, rng:range(0.5, 40), nil, angle) end
  return H.ConvexPolygon(x, y, x + size, y, x + size * 0.7, y + size, x - size * 0.2, y + size * 0.6)
end

describe('a body added to a space', function()
  it('gets the box a refresh gives, bit for bit, its vertices waiting for their first reader', function()
    local rng = PRNG.new(SEED)
    local space = S.pace()
    budget.loop(600, function(case)
      local where = ('seed %d case %d'):format(SEED, case)
      local shapes = {}
      local shape = randomShape(rng)
      if rng:next() < 0.3 then shape:scale(rng:range(0.5, 3)) end
      shapes[1] = shape
      local how = rng:int(1, 3)
      local body = shape
      if how == 2 then
        body = T.Collider(shape)
      elseif how == 3 then
        shapes[2] = randomShape(rng)
        body = T.Collider(shape, T.Collider(shapes[2]))
      end
      space:add(body)
      for i = 1, #shapes do
        assert(shapes[i][DIRTY] == true, where .. ': a shape refreshed on add')
      end
      local got = { space._tree:box(body._sid) }
      -- (the same shapes refreshed, from copies in the same pose, and the box of their bounds)
      local want = { math.huge, math.huge, -math.huge, -math.huge }
      for i = 1, #shapes do
        local x0, y0, x1, y1 = shapes[i]:copy():getBounds()
        want[1], want[2] = math.min(want[1], x0), math.min(want[2], y0)
        want[3], want[4] = math.max(want[3], x1), math.max(want[4], y1)
      end
      for k = 1, 4 do
        if got[k] ~= want[k] then
          error(('%s: box %d is %s, a refresh gives %s'):format(where, k, show(got[k]), show(want[k])))
        end
      end
      -- the vertices, when read, are a refresh's (and the bounds stay the same)
      for i = 1, #shapes do
        local own, ref = { shapes[i]:getVertices() }, { shapes[i]:copy():getVertices() }
        assert.same(ref, own, where)
        assert.same({ shapes[i]:copy():getBounds() }, { shapes[i]:getBounds() }, where)
      end
      space:remove(body)
    end)
  end)

  it('moved before its first query, gets the box of where it is', function()
    local space = S.pace()
    local c = T.Rectangle(0, 0, 10, 4, 0.5)
    local bare = H.RegularPolygon(50, 0, 5, 3)
    space:add(c)
    space:add(bare)
    c:translate(100, 0)
    bare:rotate(0.3)
    local list, n = space:queryPoint(100, 0)
    assert.equals(1, n)
    assert.equals(c, list[1])
    assert.same({ c:copy():getBounds() }, { space._tree:box(c._sid) })
    assert.same({ bare:copy():getBounds() }, { space._tree:box(bare._sid) })
  end)

  it('refreshed before, then moved and added, then moved, gets the box of where it is', function()
    -- (a shape refreshed before keeps its last bounds with the pose they were made for, which
    -- a move after the add shifts (VertexShape:_movedBounds, a box grown by a rounding's
    -- worth): only a shape never refreshed takes its bounds alone)
    for _, body in ipairs({ H.Rectangle(0, 0, 10, 4, 0.7), T.Rectangle(0, 0, 10, 4, 0.7) }) do
      local space = S.pace()
      body:getBounds()
      body:translate(100, 0)
      space:add(body)
      body:translate(30, 5)
      space:queryPoint(0, 0)
      local x0, y0, x1, y1 = body:copy():getBounds()
      local b0, b1, b2, b3 = space._tree:box(body._sid)
      assert.is_true(b0 <= x0 and b1 <= y0 and b2 >= x1 and b3 >= y1, 'the box holds the body')
      assert.is_true(x0 - b0 < 1e-9 and y0 - b1 < 1e-9 and b2 - x1 < 1e-9 and b3 - y1 < 1e-9, 'and no more')
    end
  end)
end)
