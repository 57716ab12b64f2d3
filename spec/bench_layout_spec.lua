-- bench/workloads.lua's W.layout, which places the narrow-phase bench's pairs in one Box2D
-- world (bench/lovephysics, section narrow): each pair keeps its overlap, and no body comes
-- within the gap of a body it must not meet, the cell as small as that allows. Checked with
-- strike's shapes built where the layout puts them. Reproduce a failure with
-- STRIKE_SEED=<seed> (any VM).
local S = require('strike')
local W = require('bench.workloads')
local PRNG = require('spec.helpers.prng')

local SEED = PRNG.seedFromEnv(20260612)
local GAP = 40

-- The description d with its centre moved to (x, y), as a strike shape.
local function placed(d, x, y)
  local c = {}
  for k, v in pairs(d) do c[k] = v end
  c.x, c.y = x, y
  return W.strikeShape(c)
end

-- How far apart two boxes are: the larger of the gaps along x and along y (negative when
-- they overlap).
local function boxGap(a, b)
  local ax0, ay0, ax1, ay1 = a:getBounds()
  local bx0, by0, bx1, by1 = b:getBounds()
  return math.max(bx0 - ax1, ax0 - bx1, by0 - ay1, ay0 - by1)
end

local function check(name, apart)
  local list = W.generate(name, 120, SEED)
  local ax, ay, bx, by, side = W.layout(list, apart, GAP)
  local bodies, pair = {}, {}
  local mtv = S.MTV()
  for k, p in ipairs(list) do
    local a, b = placed(p[1], ax[k], ay[k]), placed(p[2], bx[k], by[k])
    bodies[#bodies + 1], pair[#bodies + 1] = a, k
    bodies[#bodies + 1], pair[#bodies + 1] = b, k
    local where = ('seed %d (STRIKE_SEED=%d replays), %s pair %d'):format(SEED, SEED, name, k)
    if apart then
      assert(S.AT(a, b, mtv).separating, where .. ': the pair touches apart')
    else
      -- the same offset between the two, and the oracle's verdict
      assert(math.abs((bx[k] - ax[k]) - (p[2].x - p[1].x)) <= 1e-9 * side, where .. ': x offset changed')
      assert(math.abs((by[k] - ay[k]) - (p[2].y - p[1].y)) <= 1e-9 * side, where .. ': y offset changed')
      assert((not S.AT(a, b, mtv).separating) == p.hit, where .. ': the verdict changed')
    end
  end
  for i = 1, #bodies - 1 do
    for j = i + 1, #bodies do
      if apart or pair[i] ~= pair[j] then
        local g = boxGap(bodies[i], bodies[j])
        if g < GAP then
          error(('seed %d (STRIKE_SEED=%d replays), %s: bodies %d (pair %d) and %d (pair %d) %g apart, under %d')
            :format(SEED, SEED, name, i, pair[i], j, pair[j], g, GAP))
        end
      end
    end
  end
end

-- Two pairs of circles of radius r, each second circle at distance d from its first: to the
-- right in pair 1, to the left in pair 2, so that side by side on the grid the two second
-- circles face each other (or, apart, pair 1's second circle faces pair 2's first).
local function circles(r, d)
  return {
    { { kind = 'circle', x = 0, y = 0, r = r }, { kind = 'circle', x = d, y = 0, r = r } },
    { { kind = 'circle', x = 0, y = 0, r = r }, { kind = 'circle', x = -d, y = 0, r = r } },
  }
end

describe('bench.workloads: W.layout', function()
  it('keeps each poly-poly pair as it is, and the pairs apart', function() check('poly-poly', false) end)
  it('keeps each circle-poly pair as it is, and the pairs apart', function() check('circle-poly', false) end)
  it('puts every poly-poly body clear of every other with apart', function() check('poly-poly', true) end)
  it('puts every circle-poly body clear of every other with apart', function() check('circle-poly', true) end)

  it('leaves exactly the gap between two pairs whose bodies reach towards each other', function()
    -- cell 2 (d + r) + gap = 2 (50 + 10) + 5: pair 1's second circle ends 5 short of pair 2's
    local ax, ay, bx, by, side = W.layout(circles(10, 50), false, 5)
    assert.are.equal(125, side)
    assert.are.equal(ay[1], ay[2])
    assert.is_true(math.abs((bx[2] - bx[1]) - (2 * 10 + 5)) <= 1e-12)
    assert.are.equal(by[1], by[2])
    assert.are.equal(side, ax[2] - ax[1])
  end)

  it('leaves exactly the gap between a pair apart and the next pair', function()
    -- cell 2 (2 r + gap) = 2 (100 + 5), larger than 2 (d + r) + gap = 125: pair 1's second
    -- circle sits half a cell from its first and from pair 2's first
    local ax, _, bx, _, side = W.layout(circles(50, 10), true, 5)
    assert.are.equal(210, side)
    assert.are.equal(2 * 50 + 5, bx[1] - ax[1])
    assert.are.equal(2 * 50 + 5, ax[2] - bx[1])
  end)

  it('refuses compound bodies', function()
    local list = { { { kind = 'compound', parts = {} }, { kind = 'circle', x = 0, y = 0, r = 1 } } }
    local ok, err = pcall(W.layout, list, false, 1)
    assert.is_false(ok)
    assert.is_truthy(err:find('W.layout: single shapes only', 1, true))
  end)
end)
