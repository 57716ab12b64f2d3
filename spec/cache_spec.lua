-- World-space data is recomputed once per change, on the next query, never per getter.
local S = require('strike')

-- Count how often `shape` recomputes its world-space cache.
local function counted(shape)
  local n = 0
  local refresh = shape._refresh
  shape._refresh = function(self) n = n + 1 return refresh(self) end
  return function() return n end
end

describe('world-space caches', function()
  it('transforms only mark a shape dirty; the next query recomputes once', function()
    local r = S.hapes.RegularPolygon(0, 0, 8, 10)
    local count = counted(r)
    r:getBbox()
    assert.equals(1, count())
    r:translate(1, 2):rotate(0.3):scale(2):translateTo(5, 5):rotateTo(1)
    assert.equals(1, count()) -- five transforms, no work yet
    for i = 1, 8 do r:getVertex(i) end
    r:getBbox()
    r:getEdge(3)
    r:getVertices()
    r:project(1, 0)
    S.AT(r, S.hapes.Circle(0, 0, 1))
    assert.equals(2, count()) -- every query after them shares one refresh
  end)

  it('moving a collider refreshes each of its shapes once, at the next query', function()
    local a, b = S.hapes.Rectangle(0, 0, 10), S.hapes.Circle(20, 0, 5)
    local c = S.trikers.Collider(a, b)
    c:getBbox()
    local ca, cb = counted(a), counted(b)
    for _ = 1, 10 do c:translate(1, 0):rotate(0.1) end
    assert.equals(0, ca())
    assert.equals(0, cb())
    c:getBbox()
    c:getRadius()
    S.triking(c, S.trikers.Circle(100, 0, 1))
    assert.equals(1, ca())
    assert.equals(1, cb())
  end)

  it('a circle is refreshed lazily too', function()
    local c = S.hapes.Circle(0, 0, 3)
    local count = counted(c)
    c:translate(1, 1):scale(2)
    c:getBbox()
    c:getBounds()
    assert.equals(1, count())
  end)
end)
