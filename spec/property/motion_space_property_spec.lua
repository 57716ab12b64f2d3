-- Property specs for Space:cast and Space:move on seeded random worlds, with moves, adds and
-- removes in between (the candidates a move keeps must follow them): cast against a brute
-- force (S.weep of the body against every other body, the earliest), and every move ending
-- clear of every body it started clear of. Reproduce a failure with STRIKE_SEED=<seed>.
local S = require 'strike'
local PRNG = require('spec.helpers.prng')

local H, T = S.hapes, S.trikers
local abs, pi = math.abs, math.pi

local SEED = PRNG.seedFromEnv(20261124)

-- A random body near (x, y): boxes, polygons, circles, capsules, rounded boxes, edges,
-- single-shape colliders and two-shape colliders.
local function body(rng, x, y)
  local k = rng:int(1, 8)
  local a = rng:range(-pi, pi)
  if k == 1 then return H.Rectangle(x, y, rng:range(2, 30), rng:range(2, 30), a) end
  if k == 2 then return H.RegularPolygon(x, y, rng:int(3, 8), rng:range(2, 15), a) end
  if k == 3 then return H.Circle(x, y, rng:range(1, 12)) end
  if k == 4 then return H.Capsule(x, y, rng:range(2, 10), rng:range(10, 30), a) end
  if k == 5 then return H.Rectangle(x, y, rng:range(5, 30), rng:range(5, 30), a, rng:range(0.5, 2)) end
  if k == 6 then return H.Edge(x - 10, y + rng:range(-10, 10), x + 10, y + rng:range(-10, 10)) end
  if k == 7 then return T.Rectangle(x, y, rng:range(2, 30), rng:range(2, 30), a) end
  return T.Collider(H.Circle(x - 6, y, rng:range(2, 6)), H.Rectangle(x + 6, y, rng:range(4, 10), rng:range(4, 10)))
end

describe('S.pace motion against a brute force', function()
  it('cast gives the earliest S.weep over every body; a move ends clear of everything it started clear of',
    function()
      local rng = PRNG.new(SEED)
      local casts, hits, moves = 0, 0, 0
      for w = 1, 120 do
        local sp = S.pace()
        local list = {}
        for i = 1, rng:int(5, 40) do list[i] = sp:add(body(rng, rng:range(0, 300), rng:range(0, 300))) end
        local mover = sp:add(body(rng, rng:range(0, 300), rng:range(0, 300)))
        for step = 1, 30 do
          local r = rng:next()
          if r < 0.1 and #list > 1 then -- remove one
            sp:remove(table.remove(list, rng:int(1, #list)))
          elseif r < 0.2 then -- add one
            list[#list + 1] = sp:add(body(rng, rng:range(0, 300), rng:range(0, 300)))
          elseif r < 0.3 then -- move one
            list[rng:int(1, #list)]:translate(rng:range(-30, 30), rng:range(-30, 30))
          end
          local dx, dy = rng:range(-60, 60), rng:range(-60, 60)
          local why = ('seed %d world %d step %d'):format(SEED, w, step)
          -- cast against the brute force
          local h = sp:cast(mover, dx, dy)
          local best, bestBody = false, nil
          for _, b in ipairs(list) do
            local hb = S.weep(mover, dx, dy, b)
            if hb and (not best or hb.t < best) then best, bestBody = hb.t, b end
          end
          casts = casts + 1
          if best then
            hits = hits + 1
            assert(h, why .. ': cast missed, the brute force hits at t = ' .. best)
            assert(abs(h.t - best) <= 1e-9, why .. (': cast t %.17g, brute force %.17g'):format(h.t, best))
            if h.body ~= bestBody then
              local other = S.weep(mover, dx, dy, h.body)
              assert(other and abs(other.t - best) <= 1e-9, why .. ': cast chose a body hit later')
            end
          else
            assert(not h, why .. ': cast hit, the brute force misses')
          end
          -- a move: nothing it did not start in overlaps it after
          local clear = {}
          for i, b in ipairs(list) do clear[i] = not S.triking(mover, b) end
          local cx, cy = mover:getCentroid()
          sp:move(mover, cx + dx, cy + dy)
          moves = moves + 1
          for i, b in ipairs(list) do
            if clear[i] then
              local m = S.triking(mover, b)
              assert(not m, why .. (': the move ended %.3g deep in a body it started clear of'):format(
                m and m.depth or 0))
            end
          end
        end
      end
      assert(hits > casts / 5 and hits < casts * 0.95, ('hits %d of %d casts'):format(hits, casts))
      assert(moves == casts)
    end)
end)
