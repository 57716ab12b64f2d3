-- The walking support search in sat.maxSeparation must find exactly what a full scan of
-- every face against every vertex finds.
local S = require('strike')
local sat = require('strike.collide.sat')
local layout = require('strike.base.layout')
local PRNG = require('spec.helpers.prng')

local SEED = PRNG.seedFromEnv(777)

-- The O(n * m) definition: max over A's faces of min over B's vertices, the lowest face
-- among ties; and the lowest face that separates (s >= 0) with its separation, if any.
local function fullScan(A, B)
  local best, bi, firstS, firstI = -math.huge, 1, nil, nil
  for i = 1, A[layout.COUNT] do
    local nx, ny = A:getNormal(i)
    local s = math.huge
    for j = 1, B[layout.COUNT] do
      local x, y = B:getVertex(j)
      local p = nx * x + ny * y
      if p < s then s = p end
    end
    local ax, ay = A:getVertex(i)
    s = s - (nx * ax + ny * ay)
    if s > best then best, bi = s, i end
    if s >= 0 and not firstI then firstS, firstI = s, i end
  end
  return best, bi, firstS, firstI
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
        local want, wantI, firstS, firstI = fullScan(A, B)
        local got, gotI = maxSeparation(A, B)
        if want < 0 then
          -- overlapping: the same largest separation, from the same face (ties included)
          assert(got == want and gotI == wantI, ('seed %d case %d: got %.17g (face %d), full scan %.17g (face %d)')
            :format(SEED, case, got, gotI, want, wantI))
        else
          -- separated: it stops at the first separating face, the same on every VM
          assert(got == firstS and gotI == firstI,
            ('seed %d case %d: got %.17g (face %d), first separating face %d at %.17g')
            :format(SEED, case, got, gotI, firstI, firstS))
        end
      end
    end)
  end)
end

describe('centrally symmetric polygons', function()
  it('break ties like the face-by-face scan (the lowest face wins)', function()
    local H = S.hapes
    local pairsList = {
      { H.Rectangle(0, 0, 10, 10), H.Rectangle(0, 0, 10, 10) },          -- every face ties
      { H.Rectangle(0, 0, 10, 10), H.Rectangle(0, 0, 4, 4) },
      { H.RegularPolygon(5, 5, 8, 10), H.RegularPolygon(5, 5, 8, 10) },
      { H.Rectangle(0, 0, 10, 20), H.Rectangle(0, 0, 20, 10) },
      { H.Edge(-5, 0, 5, 0), H.Rectangle(0, 0, 4, 4) },                  -- both edge faces tie
      { H.Rectangle(0, 0, 10, 10), H.Rectangle(20, 0, 10, 10) },         -- separated
      { H.Rectangle(0, 0, 10, 10), H.Rectangle(-20, 0, 10, 10) },        -- separated, second half
    }
    for k, p in ipairs(pairsList) do
      for _, variant in ipairs({ 'maxSeparationWalk', 'maxSeparationScan' }) do
        local A, B = p[1], p[2]
        local want, wantI, firstS, firstI = fullScan(A, B)
        if firstI then want, wantI = firstS, firstI end
        local got, gotI = sat[variant](A, B)
        assert(got == want and gotI == wantI,
          ('%s, pair %d: got %.17g (face %d), want %.17g (face %d)'):format(variant, k, got, gotI, want, wantI))
      end
    end
  end)

  it('are recognised, with opposite normals exactly opposite, so the scan shares projections', function()
    local cases = {
      { S.hapes.Rectangle(3, 4, 10, 20, 0.3), 2 },
      { S.hapes.RegularPolygon(1e3, -2e3, 8, 17, 1.1), 4 },
      { S.hapes.RegularPolygon(0, 0, 16, 5), 8 },
      { S.hapes.Edge(0, 0, 3, 1), 1 },
      { S.hapes.ConvexPolygon(0, 0, 4, 0, 6, 3, 2, 3), 2 }, -- a parallelogram
      { S.hapes.RegularPolygon(0, 0, 5, 10), 0 },            -- odd: never
      { S.hapes.ConvexPolygon(0, 0, 4, 0, 5, 3, 1, 2), 0 },  -- a kite-ish quadrilateral
    }
    for k, c in ipairs(cases) do
      local shape, half = c[1], c[2]
      assert.equals(half, shape[layout.HALF], 'case ' .. k)
      for i = 1, half do
        local ax, ay = shape:getNormal(i)
        local bx, by = shape:getNormal(i + half)
        assert(ax == -bx and ay == -by, ('case %d: normals %d and %d are not exactly opposite'):format(k, i, i + half))
      end
    end
  end)
end)
