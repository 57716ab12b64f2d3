-- The outline rule's details: contact points of a compound MTV, seams, chains with solids,
-- the fast path's answer. (The scenes a game sees are in outline_scenes_spec.lua, the
-- minimum against an independent oracle in property/compound_mtv_property_spec.lua.)
local S = require('strike')
local expect = require('spec.helpers.expect')
local near, nearList = expect.near, expect.nearList
local H, T = S.hapes, S.trikers

local function floor(n)
  local tiles = {}
  for i = 0, n - 1 do tiles[#tiles + 1] = H.Rectangle(16 + 32 * i, 16, 32, 32) end
  return T.Collider((table.unpack or unpack)(tiles)), tiles -- luacheck: ignore 113 143
end

describe('the outline rule', function()
  it('S.ite gives the points of every member pair that touches after the push', function()
    local f, tiles = floor(5)
    local box = H.Rectangle(32, -10, 40, 40) -- x [12, 52], 10 deep across the seam x = 32
    local m = S.triking(f, box)
    nearList({ m.x, m.y }, { 0, -10 })
    local c = S.ite(m)
    assert.equals(4, c.count)
    nearList({ c.nx, c.ny }, { 0, -1 })
    -- where each tile and the box touch once the box has moved up by 10: the tiles' top face
    -- y = 0, from x = 12 to 32 on the first, 32 to 52 on the second; normal up, depth 10
    local want = { { 32, 0, tiles[1] }, { 12, 0, tiles[1] }, { 52, 0, tiles[2] }, { 32, 0, tiles[2] } }
    for i, w in ipairs(want) do
      nearList({ c[i].x, c[i].y, c[i].depth, c[i].nx, c[i].ny }, { w[1], w[2], 10, 0, -1 })
      assert.equals(w[3], c[i].colliderShape)
      assert.equals(box, c[i].collidedShape)
    end
    -- a second call reuses the tables; a moved body is tested again
    local again = S.ite(m, c)
    assert.equals(c, again)
    box:translate(0, -5)
    c = S.ite(m, c)
    assert.equals(4, c.count)
    near(c[1].depth, 5)
    box:translate(0, -6)
    assert.is_nil(S.ite(m))
  end)

  it('S.ite on a compound MTV against a circle: one point, where the circle touches after the push', function()
    -- the circle (10, 10) r 3 in the L's corner leaves by 13 through x = 0 or y = 0 (a tie):
    -- moved by the push, its centre is 13 further along it and touches the outline 3 before
    -- that centre, so the point is 10 along the push from (10, 10), on the outline, 13 deep
    local L = T.Concave(0, 0, 100, 0, 100, 20, 20, 20, 20, 100, 0, 100)
    local m = S.triking(L, H.Circle(10, 10, 3))
    near(m.depth, 13)
    local c = S.ite(m)
    assert.equals(1, c.count)
    nearList({ c[1].x, c[1].y, c[1].depth, c[1].nx, c[1].ny }, { 10 + 10 * m.nx, 10 + 10 * m.ny, 13, m.nx, m.ny })
  end)

  it('a point inside a Concave outline leaves through the outline, never onto a seam', function()
    local L = T.Concave(0, 0, 100, 0, 100, 20, 20, 20, 20, 100, 0, 100)
    for _, p in ipairs({ { 11, 10, 0, -10 }, { 10, 11, -10, 0 }, { 19, 18.5, 1, 1.5 } }) do
      local m = S.triking(L, H.Point(p[1], p[2]))
      nearList({ m.x, m.y }, { p[3], p[4] }, 1e-9)
    end
  end)

  it('chain segments keep their own answer; the deeper of theirs and the solids\' wins', function()
    local level = T.Collider(T.Chain(-50, 0, 0, 0, 50, 0), H.Rectangle(30, -20, 10, 40))
    -- a box 2 into the ground, far from the wall: the chain's push, up
    local m = S.triking(level, H.Rectangle(-20, -3, 10, 10))
    nearList({ m.x, m.y }, { 0, -2 })
    -- x [17, 27]: 2 into the wall (x [25, 35]), and 1 into the ground: the wall's push
    m = S.triking(level, H.Rectangle(22, -4, 10, 10))
    nearList({ m.x, m.y }, { -2, 0 })
  end)

  it('keeps the deepest pair\'s own MTV when it is free (single pairs unchanged)', function()
    local L = T.Concave(0, 0, 100, 0, 100, 20, 20, 20, 20, 100, 0, 100)
    local box = H.Rectangle(60, 24, 10, 10) -- y [19, 29]: 1 into the arm, far from the seam
    local m = S.triking(L, box)
    nearList({ m.x, m.y }, { 0, 1 })
    assert.is_true(m.edgeIndex ~= 0) -- (a face of a piece: the pair's own answer)
    assert.equals(m.depth, S.AT(m.colliderShape, m.collidedShape).depth)
  end)
end)
