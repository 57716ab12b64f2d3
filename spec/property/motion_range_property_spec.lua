-- Property spec for the range of motion and the skin (docs/moving.md, "Moving bodies in a
-- space": the stop, exact fits; limits.lua: the range): seeded random worlds at random scales
-- (1e-3 to 1e3) and random offsets from the origin (up to 3e6 scales away, within the range),
-- with random moves through them. Checked with S.triking alone, independently of the move code:
--  * a move ('slide', the default) never ends overlapping a body it started clear of;
--  * a stop ('touch') is within the skin: the body is apart from what it met, and S.eparation
--    finds it no farther from it than the skin (SKIN times its radius) along the normal allows
--    on the way back to the touch (the skin over the cosine of the move with the normal).
-- Half the bodies are axis-aligned boxes of whole sizes, some of them in rows that touch
-- (floors, walls, gaps exactly a box wide), and a third of the moves go along an axis, so
-- that exact touches and exact fits come up as often as the skin. Reproduce a failure with
-- STRIKE_SEED=<seed>.
local S = require 'strike'
local PRNG = require('spec.helpers.prng')

local H, T = S.hapes, S.trikers
local pi = math.pi

local SEED = PRNG.seedFromEnv(20261124)
local SKIN = S.pace().SKIN

-- A random body near (x, y) at scale s: the kinds of motion_space_property_spec, and
-- axis-aligned boxes of whole sizes.
local function body(rng, x, y, s)
  local k = rng:int(1, 16)
  local a = rng:range(-pi, pi)
  if k == 1 then return H.Rectangle(x, y, rng:range(2, 30) * s, rng:range(2, 30) * s, a) end
  if k == 2 then return H.RegularPolygon(x, y, rng:int(3, 8), rng:range(2, 15) * s, a) end
  if k == 3 then return H.Circle(x, y, rng:range(1, 12) * s) end
  if k == 4 then return H.Capsule(x, y, rng:range(2, 10) * s, rng:range(10, 30) * s, a) end
  if k == 5 then return H.Rectangle(x, y, rng:range(5, 30) * s, rng:range(5, 30) * s, a, rng:range(0.5, 2) * s) end
  if k == 6 then return H.Edge(x - 10 * s, y + rng:range(-10, 10) * s, x + 10 * s, y + rng:range(-10, 10) * s) end
  if k == 7 then return T.Rectangle(x, y, rng:range(2, 30) * s, rng:range(2, 30) * s, a) end
  if k == 8 then
    return T.Collider(H.Circle(x - 6 * s, y, rng:range(2, 6) * s),
      H.Rectangle(x + 6 * s, y, rng:range(4, 10) * s, rng:range(4, 10) * s))
  end
  return H.Rectangle(x, y, rng:int(1, 8) * 4 * s, rng:int(1, 8) * 4 * s) -- (axis-aligned, whole)
end

-- A row of n axis-aligned boxes w x h that touch, from (x, y) along x or y.
local function row(rng, sp, list, x, y, s)
  local w, h, n = rng:int(1, 4) * 8 * s, rng:int(1, 4) * 8 * s, rng:int(2, 6)
  local alongX = rng:next() < 0.5
  for i = 0, n - 1 do
    list[#list + 1] = sp:add(H.Rectangle(x + (alongX and i * w or 0), y + (alongX and 0 or i * h), w, h))
  end
end

-- A random move of length up to 60 scales: a third of them along an axis.
local function move(rng, s)
  local dx, dy = rng:range(-60, 60) * s, rng:range(-60, 60) * s
  local r = rng:next()
  if r < 1 / 6 then dx = 0 elseif r < 1 / 3 then dy = 0 end
  return dx, dy
end

describe('the range of motion against S.triking', function()
  it('moves at every scale and offset inside the range end clear, and stop within the skin', function()
    local rng = PRNG.new(SEED)
    local moves, stops = 0, 0
    for w = 1, 150 do
      local s = 10 ^ rng:range(-3, 3)
      local ox = (rng:next() < 0.5 and -1 or 1) * s * 10 ^ rng:range(0, 6.5)
      local oy = (rng:next() < 0.5 and -1 or 1) * s * 10 ^ rng:range(0, 6.5)
      local sp = S.pace()
      local list = {}
      for _ = 1, rng:int(5, 25) do
        list[#list + 1] = sp:add(body(rng, ox + rng:range(0, 300) * s, oy + rng:range(0, 300) * s, s))
      end
      for _ = 1, rng:int(1, 4) do row(rng, sp, list, ox + rng:range(0, 300) * s, oy + rng:range(0, 300) * s, s) end
      local mx, my, mw, mh = ox + rng:range(0, 300) * s, oy + rng:range(0, 300) * s, rng:int(1, 4) * 8 * s,
        rng:int(1, 4) * 8 * s
      local fit = rng:next() < 0.5
      local mover = sp:add(fit and H.Rectangle(mx, my, mw, mh) or body(rng, mx, my, s))
      local skin = SKIN * mover:getRadius()
      local sx, sy = rng:next() < 0.5 and -1 or 1, rng:next() < 0.5 and -1 or 1
      if fit then
        -- (bump.lua's "when sliding", turned and scaled to the mover: a shaft exactly its size,
        -- its wall half the mover's height lower, so that the mover does not start level with
        -- the wall's top: a body within the rounding of a surface's level may end within it)
        list[#list + 1] = sp:add(H.Rectangle(mx, my + 2.5 * mh * sy, mw, 2 * mh))
        list[#list + 1] = sp:add(H.Rectangle(mx + 2 * mw * sx, my + 1.5 * mh * sy, mw, mh))
      end
      for step = 1, 30 do
        local why = ('seed %d world %d step %d (scale %.3g, offset %.3g, %.3g)'):format(SEED, w, step, s, ox, oy)
        local clear = {}
        for i, b in ipairs(list) do clear[i] = not S.triking(mover, b) end
        local cx, cy = mover:getCentroid()
        local dx, dy = move(rng, s)
        if fit and step <= 2 then dx, dy = 5 * mw * sx, 5 * mh * sy end -- (into the shaft)
        if step % 2 == 0 then
          -- a slide: nothing it started clear of overlaps it after
          sp:move(mover, cx + dx, cy + dy)
          moves = moves + 1
        else
          -- a stop: apart from what it met, and within the skin of it
          local _, _, cols, n = sp:move(mover, cx + dx, cy + dy, function() return 'touch' end)
          moves = moves + 1
          local col = n > 0 and cols[1]
          if col and not col.overlapping then
            -- apart from what it met, and no farther from it than the way back to the touch:
            -- the skin along the normal, taken back along the leg (the leg: the move, which a
            -- fit may have shifted, unchanged)
            local other = col.other
            assert(not S.triking(mover, other), why .. ': the stop overlaps what it met')
            local dn = -(dx * col.nx + dy * col.ny)
            if dn > 0 then
              stops = stops + 1
              local far = skin * math.sqrt(dx * dx + dy * dy) / dn
              local d = S.eparation(mover, other)
              assert(d <= far, why .. (': the stop is %.3g from what it met, more than the skin (%.3g) along the'
                .. ' normal (%.3g, %.3g) allows (%.3g)'):format(d, skin, col.nx, col.ny, far))
            end
          end
        end
        for i, b in ipairs(list) do
          if clear[i] then
            local m = S.triking(mover, b)
            assert(not m, why .. (': the move ended %.3g deep (%.3g skins) in a body it started clear of')
              :format(m and m.depth or 0, m and m.depth / skin or 0))
          end
        end
      end
    end
    assert(moves == 150 * 30)
    assert(stops > 300, 'only ' .. stops .. ' stops checked')
  end)
end)
