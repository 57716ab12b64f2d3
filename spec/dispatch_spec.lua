-- The operation tables (strike/collide/dispatch.lua): one registration per ordered pair of
-- kinds fills the reversed order; kinds and pairs without kernels give clear errors.
local S = require('strike')
local dispatch = require('strike.collide.dispatch')
local sat = require('strike.collide.sat')
local expect = require('spec.helpers.expect')
local raisesAt = expect.raisesAt

-- A shape kind of the spec's own: circles whose narrow phase against circles is the
-- circle kernel, written for (kind, circle) only, with a record of its calls.
local calls = {}
dispatch.registerKind('specBlob', { ray = function() return nil end })
dispatch.register('specBlob', 'circle', {
  collide = function(a, b, out, flip)
    calls[#calls + 1] = { a = a, b = b, flip = flip or false }
    if flip then return sat.circleCircle(b, a, out) end
    return sat.circleCircle(a, b, out)
  end,
  contact = dispatch.pair.circle.circle.contact,
})
local Blob = S.hapes.Circle:extend()
Blob.kind = 'specBlob'
S.hapes.SpecBlob = Blob

describe('dispatch.register', function()
  it('fills the reversed order: (circle, kind) calls the kernel with the arguments swapped and flip', function()
    local blob, circle = S.hapes.SpecBlob(0, 0, 2), S.hapes.Circle(3, 0, 2)
    for k in pairs(calls) do calls[k] = nil end
    local m1 = S.AT(blob, circle)
    local m2 = S.AT(circle, blob)
    assert.equals(2, #calls)
    assert.equals(blob, calls[1].a)
    assert.equals(false, calls[1].flip)
    assert.equals(blob, calls[2].a) -- the registered order, whichever order S.AT was given
    assert.equals(circle, calls[2].b)
    assert.equals(true, calls[2].flip)
    assert.equals(1, m1.depth)
    assert.equals(1, m2.depth)
    assert.equals(1, m1.nx) -- from the blob toward the circle
    assert.equals(-1, m2.nx) -- from the circle toward the blob
    assert.equals(circle, m2.colliderShape)
    assert.equals(blob, m2.collidedShape)
  end)

  it('fills the reversed order of the contact kernel: the same point either way round', function()
    local blob, circle = S.hapes.SpecBlob(0, 0, 2), S.hapes.Circle(3, 0, 2)
    local c1 = S.ite(S.AT(blob, circle))
    local c2 = S.ite(S.AT(circle, blob))
    assert.equals(1, c1.count)
    assert.equals(1, c2.count)
    assert.equals(c1[1].x, c2[1].x)
    assert.equals(c1[1].y, c2[1].y)
    assert.equals(1.5, c1[1].x)
  end)

  it('leaves the distance and time-of-impact slots false until a kernel is registered', function()
    assert.equals(false, dispatch.pair.specBlob.circle.distance)
    assert.equals(false, dispatch.pair.circle.specBlob.toi)
  end)

  it('refuses a pair without a collide or a contact kernel, or of unregistered kinds', function()
    assert.has_error(function() dispatch.register('specBlob', 'specBlob', { contact = function() end }) end,
      'dispatch.register: (specBlob, specBlob) needs a collide kernel')
    assert.has_error(function() dispatch.register('specBlob', 'specBlob', { collide = function() end }) end,
      'dispatch.register: (specBlob, specBlob) needs a contact kernel')
    assert.has_error(function() dispatch.register('specNone', 'circle', {}) end,
      'dispatch.register: register the kinds "specNone" and "circle" first')
    assert.has_error(function() dispatch.registerKind('specBad', {}) end,
      'dispatch.registerKind: kind "specBad" needs a ray function')
  end)
end)

describe('a pair of kinds without a narrow phase', function()
  local blob, other = S.hapes.SpecBlob(0, 0, 2), S.hapes.SpecBlob(1, 0, 2)

  it('S.AT names both kinds, at the caller\'s line', function()
    raisesAt(function() S.AT(blob, other) end, 'strike.AT: no narrow phase for kinds specBlob and specBlob')
  end)

  it('S.triking names both kinds, for single shapes and inside colliders', function()
    raisesAt(function() S.triking(blob, other) end, 'strike.triking: no narrow phase for kinds specBlob and specBlob')
    local c = S.trikers.Collider(S.hapes.SpecBlob(0, 0, 2), S.hapes.Circle(50, 0, 1))
    raisesAt(function() S.triking(c, other) end, 'strike.triking: no narrow phase for kinds specBlob and specBlob')
  end)

  it('S.ite on a hand-made MTV between them names both kinds', function()
    local m = S.MTV(1, 0, blob, other)
    raisesAt(function() S.ite(m) end, 'strike.ite: no narrow phase for kinds specBlob and specBlob')
  end)
end)

describe('contact ids of a pair registered the other way round', function()
  -- The id's side (see contact.lua): 0 when the reference face is the MTV's first shape's.
  local function side(id) return math.floor(id / (4 * 65536 * 65536)) end

  it('name the side as the MTV orders the shapes, for (polygon, chain) as for (chain, polygon)', function()
    local floor = S.trikers.Chain(0, 0, 100, 0) -- free side above on a LÖVE screen (y down)
    local seg = (floor:unpack())
    local box = S.hapes.Rectangle(50, -5, 10, 10, 0.3) -- a corner about 1.25 px into the floor
    local m1 = S.AT(box, seg)
    local m2 = S.AT(seg, box)
    assert.is_false(m1.separating)
    assert.equals(-1, m1.edgeIndex) -- the chain's face, the second shape's
    assert.equals(1, m2.edgeIndex)
    local c1, c2 = S.ite(m1), S.ite(m2)
    assert.equals(1, c1.count)
    assert.equals(1, c2.count)
    for i = 1, 1 do
      assert.equals(1, side(c1[i].id))
      assert.equals(0, side(c2[i].id))
    end
  end)
end)
