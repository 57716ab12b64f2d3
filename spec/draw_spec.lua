-- LÖVE drawing, against a stand-in love.graphics that records every call.
local S = require('strike')
local expect = require('spec.helpers.expect')
local raisesAt = expect.raisesAt
local H, T = S.hapes, S.trikers

local calls, colour
local function fakeLove()
  calls, colour = {}, { 0.1, 0.2, 0.3, 0.4 }
  -- (tables are copied: strike reuses its vertex list between calls)
  local function record(name)
    return function(...)
      local call = { name, ... }
      for i, v in ipairs(call) do
        if type(v) == 'table' then
          local copy = {}
          for k, x in ipairs(v) do copy[k] = x end
          call[i] = copy
        end
      end
      calls[#calls + 1] = call
    end
  end
  return { graphics = {
    polygon = record('polygon'), line = record('line'), circle = record('circle'), points = record('points'),
    arc = record('arc'),
    getColor = function() return colour[1], colour[2], colour[3], colour[4] end,
    setColor = function(r, g, b, a) colour = { r, g, b, a } end,
  } }
end

local function names()
  local list = {}
  for i, c in ipairs(calls) do list[i] = c[1] end
  return list
end

describe('drawing', function()
  before_each(function() rawset(_G, 'love', fakeLove()) end)
  after_each(function() rawset(_G, 'love', nil) end)

  it('draws every kind of shape, in line or fill mode', function()
    H.Rectangle(0, 0, 2):draw()
    H.Circle(1, 2, 3):draw('fill')
    H.Edge(0, 0, 4, 0):draw()
    H.Point(5, 6):draw()
    assert.same({ 'polygon', 'circle', 'line', 'points' }, names())
    assert.equals('line', calls[1][2])
    expect.nearList(calls[1][3], { -1, -1, 1, -1, 1, 1, -1, 1 })
    assert.same({ 'circle', 'fill', 1, 2, 3 }, calls[2])
    assert.same({ 'line', 0, 0, 4, 0 }, calls[3])
    assert.same({ 'points', 5, 6 }, calls[4])
  end)

  it('draws a rounded shape with arcs about its core corners and its faces moved out', function()
    H.Rectangle(0, 0, 10, 10, 0, 2):draw('line')
    assert.same({ 'arc', 'line', 'arc', 'line', 'arc', 'line', 'arc', 'line' }, names())
    -- corner 1 (-3, -3): from the -x face's normal (angle pi) a quarter turn to -y's (3 pi / 2)
    local a = calls[1]
    assert.same({ 'arc', 'line', 'open', -3, -3, 2 }, { a[1], a[2], a[3], a[4], a[5], a[6] })
    expect.near(a[7], math.pi)
    expect.near(a[8], 1.5 * math.pi)
    expect.nearList({ calls[2][2], calls[2][3], calls[2][4], calls[2][5] }, { -3, -5, 3, -5 })
    H.Capsule(0, 0, 4, 10):draw('fill')
    local fill = {}
    for i = 9, #calls do fill[#fill + 1] = calls[i][1] end
    assert.same({ 'arc', 'polygon', 'arc', 'polygon' }, fill) -- (two half discs, two strips)
    assert.equals('pie', calls[9][3])
    expect.near(calls[9][8] - calls[9][7], math.pi)
    -- filled with a core polygon: love.graphics.polygon gets the vertex list alone (a count
    -- after it would be read as a coordinate)
    H.Rectangle(0, 0, 10, 10, 0, 2):draw('fill')
    local last = calls[#calls]
    assert.equals(3, #last)
    assert.same({ 'polygon', 'fill' }, { last[1], last[2] })
    expect.nearList(last[3], { -3, -3, 3, -3, 3, 3, -3, 3 })
  end)

  it('draws every shape of a collider, nested ones too', function()
    T.Collider(H.Rectangle(0, 0, 2), T.Collider(H.Circle(5, 0, 1))):draw('line')
    assert.same({ 'polygon', 'circle' }, names())
  end)

  it('S.howMTV draws a colliding MTV and restores the colour', function()
    S.howMTV(S.AT(H.Rectangle(0, 0, 10), H.Rectangle(8, 0, 10)))
    assert.same({ 'line', 'line' }, names())
    assert.same({ 'line', 0, 0, 2, 0 }, calls[2])
    assert.same({ 0.1, 0.2, 0.3, 0.4 }, colour)
    calls = {}
    S.howMTV(S.AT(H.Rectangle(0, 0, 10), H.Rectangle(30, 0, 10)))
    assert.same({}, names())
  end)

  it('S.howNorms draws a normal per edge and eight per circle', function()
    S.howNorms(T.Collider(H.Rectangle(0, 0, 2), H.Circle(5, 0, 1)), 10)
    assert.equals(4 + 8, #calls)
    assert.same({ 'line', 0, -1, 0, -11 }, calls[1])
    assert.same({ 0.1, 0.2, 0.3, 0.4 }, colour)
  end)

  it('S.howProj draws both projections, S.howContacts the points, S.howRay the ray', function()
    local m = S.AT(H.Rectangle(0, 0, 10), H.Rectangle(8, 0, 10))
    S.howProj(m)
    assert.same({ 'line', 'line' }, names())
    calls = {}
    S.howContacts(S.ite(m))
    assert.same({ 'circle', 'line', 'circle', 'line' }, names())
    calls = {}
    assert.equals(4, S.howRay(H.Rectangle(0, 0, 2), -5, 0, 1, 0))
    assert.same({ 'line', 'circle', 'line' }, names())
    assert.same({ 0.1, 0.2, 0.3, 0.4 }, colour)
    S.howContacts(nil)
  end)

  it('S.howContacts draws each point of a compound MTV along its own normal', function()
    -- the box [17, 27]^2 pushed (3, 3) out of the inner corner of an L of two bars: the points
    -- (20, 20) and (30, 20) with the normal (0, 1), (20, 20) and (20, 30) with (1, 0)
    local L = T.Collider(H.Rectangle(50, 10, 100, 20), H.Rectangle(10, 50, 20, 100))
    S.howContacts(S.ite(S.triking(L, H.Rectangle(22, 22, 10, 10))), 10)
    local lines = {}
    for _, c in ipairs(calls) do
      if c[1] == 'line' then lines[#lines + 1] = ('%g %g %g %g'):format(c[2], c[3], c[4], c[5]) end
    end
    table.sort(lines)
    assert.same({ '20 20 20 30', '20 20 30 20', '20 30 30 30', '30 20 30 30' }, lines)
  end)

  it('rejects bad arguments at the caller line', function()
    raisesAt(function() H.Circle(0, 0, 1):draw('dots') end, "strike:draw: mode must be 'line' or 'fill', got string")
    raisesAt(function() S.howMTV(42) end, 'strike.howMTV: argument 1 must be an MTV, got 42')
    raisesAt(function() S.howNorms({}) end, 'strike.howNorms: argument 1 must be a strike shape or collider')
    raisesAt(function() S.howProj(S.MTV(1, 0)) end, 'strike.howProj: the MTV must come from S.AT or S.triking')
    raisesAt(function() S.howContacts(5) end, 'strike.howContacts: argument 1 must be the result of S.ite')
    raisesAt(function() S.howRay(H.Circle(0, 0, 1), 0, 0, 0, 0) end, 'the direction must not be zero')
  end)
end)

describe('drawing without LÖVE', function()
  it('is a clear error, and loading strike never needs it', function()
    rawset(_G, 'love', nil)
    raisesAt(function() H.Circle(0, 0, 1):draw() end,
      'strike:draw: drawing needs LÖVE (love.graphics is not available)')
    raisesAt(function() S.howMTV(S.MTV()) end, 'strike.howMTV: drawing needs LÖVE')
  end)
end)
