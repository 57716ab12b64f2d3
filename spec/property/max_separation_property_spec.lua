-- The walking support search in sat.maxSeparation must find exactly what a full scan of
-- every face against every vertex finds.
local S = require('strike')
local sat = require('strike.collide.sat')
local PRNG = require('spec.helpers.prng')

local SEED = PRNG.seedFromEnv(777)

-- The O(n * m) definition: max over A's faces of min over B's vertices.
local function fullScan(A, B)
  local best, bi = -math.huge, 1
  for i = 1, A._n do
    local nx, ny = A._wnx[i], A._wny[i]
    local s = math.huge
    for j = 1, B._n do
      local p = nx * B._wx[j] + ny * B._wy[j]
      if p < s then s = p end
    end
    s = s - A._wd[i]
    if s > best then best, bi = s, i end
  end
  return best, bi
end

-- An angle: often a multiple of a quarter turn, so that edges of the two shapes are
-- parallel or perpendicular (projections tie), else anything.
local function angle(rng)
  if rng:next() < 0.4 then return rng:int(0, 3) * math.pi / 2 end
  return rng:range(0, 7)
end

local function randomShape(rng)
  local kind = rng:int(1, 4)
  local x, y = rng:range(-50, 50), rng:range(-50, 50)
  if rng:next() < 0.4 then x, y = rng:int(-50, 50), rng:int(-50, 50) end
  if kind == 1 then return S.hapes.Rectangle(x, y, rng:int(1, 60), rng:int(1, 60), angle(rng)) end
  if kind == 2 then return S.hapes.RegularPolygon(x, y, 2 * rng:int(2, 12), rng:int(1, 40), angle(rng)) end
  if kind == 3 then
    local pts = {}
    for k = 1, 2 * rng:int(3, 12) do pts[k] = rng:range(-40, 40) end
    local ok, shape = pcall(S.hapes.ConvexPolygon, (function()
      -- scatter around (x, y); the hull makes any point set convex
      for k = 1, #pts, 2 do pts[k], pts[k + 1] = x + pts[k], y + pts[k + 1] end
      return pts
    end)())
    if ok then return shape end
    return S.hapes.Rectangle(x, y, 5, 5)
  end
  local a, l = angle(rng), rng:int(1, 40)
  return S.hapes.Edge(x, y, x + l * math.cos(a), y + l * math.sin(a))
end

for _, variant in ipairs({ 'maxSeparationWalk', 'maxSeparationScan' }) do
  describe('sat.' .. variant, function()
    it('agrees exactly with the full scan, whenever it does not stop early', function()
      local maxSeparation = sat[variant]
      local rng = PRNG.new(SEED)
      for case = 1, 3000 do
        local A, B = randomShape(rng), randomShape(rng)
        A:getBbox()
        B:getBbox()
        local want, wantI = fullScan(A, B)
        local got, gotI = maxSeparation(A, B)
        if want < 0 then
          assert(got == want, ('seed %d case %d: walked %.17g (face %d), full scan %.17g (face %d)')
            :format(SEED, case, got, gotI, want, wantI))
        else
          -- separated: it stops at the first separating face, which the full scan confirms
          assert(got >= 0, ('seed %d case %d: walked %.17g but the full scan separates at %.17g')
            :format(SEED, case, got, want))
          local nx, ny = A._wnx[gotI], A._wny[gotI]
          local s = math.huge
          for j = 1, B._n do s = math.min(s, nx * B._wx[j] + ny * B._wy[j]) end
          assert(s - A._wd[gotI] == got, ('seed %d case %d: face %d does not separate'):format(SEED, case, gotI))
        end
      end
    end)
  end)
end
