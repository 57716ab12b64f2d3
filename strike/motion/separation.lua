--- S.eparation: how far apart two bodies are, and where.
---
--- Separated bodies: the smallest distance over every pair of their leaves, each pair's
--- the distance between the leaves' cores (motion/kernels.lua: exact, from the closest
--- vertex-edge pair of two disjoint convex cores) less both radii, with the closest points
--- on the two surfaces. Overlapping bodies (as S.triking says): minus S.triking's depth, and
--- the points of each that reach deepest into the other along its MTV. Bodies that S.triking
--- does not find colliding are never closer than 0: two members of one collider, a shape
--- behind a chain segment (one-sided), or a contact within round-off.
local ROOT = (...):match('^(.-)%.motion%.[^%.]+$')
local kernels = require(ROOT .. '.motion.kernels')
local sweep = require(ROOT .. '.motion.sweep')
local layout = require(ROOT .. '.base.layout')
local compound = require(ROOT .. '.collide.compound')
local MTV = require(ROOT .. '.collide.MTV')

local R = layout.R
local coreDistance, support, leavesOf, checkBody = kernels.coreDistance, kernels.support, sweep.leavesOf,
  sweep.checkBody
local collide = compound.collide
local sqrt, huge = math.sqrt, math.huge

local separation = {}

local mtv = MTV()
local one1, one2 = {}, {}
local FNAME = 'strike.eparation'


--- The distance between two bodies (minus the depth when they overlap) and the closest
--- points on a and on b (see the header).
---@param a strike.Collider|strike.Shape
---@param b strike.Collider|strike.Shape
---@return number d
---@return number ax
---@return number ay
---@return number bx
---@return number by
function separation.eparation(a, b)
  checkBody(FNAME, a, 1)
  checkBody(FNAME, b, 2)
  local la, na = leavesOf(a, one1, FNAME, 'argument 1') -- (first: they check the leaves' kinds)
  local lb, nb = leavesOf(b, one2, FNAME, 'argument 2')
  local m = collide(a, b, mtv)
  if m then
    local nx, ny = m.nx, m.ny
    local ax, ay = support(m.colliderShape, nx, ny)
    local bx, by = support(m.collidedShape, -nx, -ny)
    return -m.depth, ax, ay, bx, by
  end
  local best, bax, bay, bbx, bby = huge, 0, 0, 0, 0
  for i = 1, na do
    local A = la[i]
    for j = 1, nb do
      local B = lb[j]
      local d, ax, ay, bx, by = coreDistance(A, B)
      d = d - A[R] - B[R]
      if d < best then
        local l = sqrt((bx - ax) ^ 2 + (by - ay) ^ 2)
        if l > 0 then -- the surface points, along the line of the core points
          local ux, uy = (bx - ax) / l, (by - ay) / l
          ax, ay, bx, by = ax + ux * A[R], ay + uy * A[R], bx - ux * B[R], by - uy * B[R]
        end
        best, bax, bay, bbx, bby = d, ax, ay, bx, by
      end
    end
  end
  if best <= 0 then -- (touching as far as S.triking is concerned: see the header)
    local mx, my = (bax + bbx) / 2, (bay + bby) / 2
    return 0, mx, my, mx, my
  end
  return best, bax, bay, bbx, bby
end

return separation
