-- The headless demo (examples/demo.lua, `make demo`): its report and its SVG picture, and its
-- line on space:move from the LÖVE demo's Platformer scene.
local demo = require('examples.demo')

local function read(path)
  local f = assert(io.open(path, 'r'))
  local text = f:read('*a')
  f:close()
  return text
end

-- Well-formed enough for a picture: one root, every element closed, in order.
local function wellFormed(text)
  local stack = {}
  for close, name, selfClosing in text:gmatch('<(/?)([%a][%w:-]*)[^>]-(/?)>') do
    if close == '/' then
      if stack[#stack] ~= name then return false, 'unexpected </' .. name .. '>' end
      stack[#stack] = nil
    elseif selfClosing ~= '/' then
      stack[#stack + 1] = name
    end
  end
  if #stack > 0 then return false, 'unclosed <' .. stack[#stack] .. '>' end
  return true
end

local function count(text, pattern)
  local n = 0
  for _ in text:gmatch(pattern) do n = n + 1 end
  return n
end

describe('the headless demo', function()
  it('reports the scene and draws every shape, MTV, contact point and the ray', function()
    local path = os.tmpname()
    finally(function() os.remove(path) end)
    local lines = {}
    local summary = demo.run(path, function(s) lines[#lines + 1] = s end)
    local report = table.concat(lines)
    assert.matches('picture written to ' .. path:gsub('%p', '%%%0'), report)
    assert.is_true(summary.collisions >= 4)
    local svg = read(path)
    assert.matches('^<%?xml', svg)
    assert(wellFormed(svg))
    assert.equals(1, count(svg, '<svg '))
    assert.equals(summary.shapes, count(svg, 'class="shape"'))
    assert.equals(summary.collisions, count(svg, 'class="mtv"'))
    assert.equals(summary.contacts, count(svg, 'class="contact"'))
    assert.equals(1, count(svg, 'class="ray"'))
    assert.equals(1, count(svg, 'class="query"'))
    assert.equals(1, count(svg, 'class="normal"'))
    -- the arrows are drawn longer than the MTVs: both the picture and the report say so
    assert.equals(1, count(svg, 'class="legend"'))
    assert.matches('<text class="legend"[^>]*>[^<]*drawn 4× their length', svg)
    assert.matches('MTV arrow is drawn 4 times its length', report)
    local shapes = 0
    for _, item in ipairs(demo.scene()) do shapes = shapes + item.body:getShapeCount() end
    assert.equals(shapes, summary.shapes)
  end)

  -- The report's space query and ray cast, against values computed here from a fresh copy of
  -- the scene without a space: S.triking with the query's rectangle, and each body's rayCast.
  it('reports a space query: the bodies that overlap its rectangle exactly, in the order they were added',
    function()
      local S = require('strike')
      local lines = {}
      local path = os.tmpname()
      finally(function() os.remove(path) end)
      local summary = demo.run(path, function(s) lines[#lines + 1] = s end)
      local report = table.concat(lines)
      local x, y, w, h = demo.QUERY[1], demo.QUERY[2], demo.QUERY[3], demo.QUERY[4]
      local rect = S.trikers.Rectangle(x + w / 2, y + h / 2, w, h)
      local expected, boxOnly = {}, {}
      for _, item in ipairs(demo.scene()) do
        local x0, y0, x1, y1 = item.body:getBounds()
        if S.triking(rect, item.body) then
          expected[#expected + 1] = item.name
        elseif x0 < x + w and x1 > x and y0 < y + h and y1 > y then
          boxOnly[#boxOnly + 1] = item.name
        end
      end
      assert.is_true(#expected >= 2) -- (a query worth showing: several bodies,
      assert.is_true(#boxOnly >= 1) --  and one that a test of boxes alone would list)
      assert.same(expected, summary.query)
      local line = ('space:queryRect(%s, %s, %s, %s) over the %d bodies in an S.pace: %d found: %s\n'):format(x, y, w,
        h, #demo.scene(), #expected, table.concat(expected, ', '))
      assert.is_truthy(report:find(line, 1, true), 'expected the line: ' .. line)
      assert.is_truthy(report:find(('the bounding box of %s overlaps the rectangle, the shape does not')
        :format(table.concat(boxOnly, ', ')), 1, true))
    end)

  it('reports a ray cast through the space: the closest body hit, its distance, point and normal', function()
    local lines = {}
    local path = os.tmpname()
    finally(function() os.remove(path) end)
    local summary = demo.run(path, function(s) lines[#lines + 1] = s end)
    local report = table.concat(lines)
    local ox, oy, dx, dy = demo.RAY[1], demo.RAY[2], demo.RAY[3], demo.RAY[4]
    local best -- the closest hit over every body (ties: the first in the scene, as the space)
    for _, item in ipairs(demo.scene()) do
      local t, hx, hy, nx, ny = item.body:rayCast(ox, oy, dx, dy)
      if t and (not best or t < best.distance) then
        best = { name = item.name, distance = t, x = hx, y = hy, nx = nx, ny = ny }
      end
    end
    assert.is_table(best)
    local ray = summary.ray
    assert.equals(best.name, ray.name)
    assert.equals(best.name, summary.rayHit)
    for _, k in ipairs({ 'distance', 'x', 'y', 'nx', 'ny' }) do assert.near(best[k], ray[k], 1e-9, k) end
    -- the hit point lies on the ray, at that distance (dx, dy need not be a unit vector)
    local l = math.sqrt(dx * dx + dy * dy)
    assert.near(ox + dx / l * best.distance, ray.x, 1e-9)
    assert.near(oy + dy / l * best.distance, ray.y, 1e-9)
    assert.near(1, ray.nx * ray.nx + ray.ny * ray.ny, 1e-9)
    local f = function(v) return ('%.1f'):format(v) end
    local line = ('space:rayCast from (%s, %s) along (%s, %s): first hit %s at (%s, %s), distance %s,'
      .. ' normal (%.2f, %.2f)\n'):format(ox, oy, dx, dy, best.name, f(best.x), f(best.y), f(best.distance), best.nx,
      best.ny)
    assert.is_truthy(report:find(line, 1, true), 'expected the line: ' .. line)
  end)

  it('reports space:move in the Platformer scene: where the character got to and the bullets, none passed',
    function()
      local S = require('strike')
      local platformer = require('demo.scenes.platformer')
      local lines = {}
      local path = os.tmpname()
      finally(function() os.remove(path) end)
      local summary = demo.run(path, function(s) lines[#lines + 1] = s end)
      local report = table.concat(lines)
      -- the scene itself, driven as LÖVE drives it: one update of 1/60 s per step
      local state = platformer.new(S, 800, 600)
      for _ = 1, demo.MOTION_STEPS do platformer.update(state, 1 / 60) end
      local x, y = state.character:getCentroid()
      local st = state.stats
      local surfaces = 0
      for _ in pairs(state.touched) do surfaces = surfaces + 1 end
      local m = summary.motion
      assert.same({ x = x, y = y, ground = state.grounded and state.names[state.ground] or nil, surfaces = surfaces,
        fired = st.fired, stopped = st.stopped, passed = st.passed }, m)
      assert.equals(0, m.passed)
      assert.is_true(m.stopped > 0 and m.fired >= m.stopped)
      assert.is_true(state.touched['one-way platform'] and state.touched['slope 45°'] and state.touched['step 6'])
      local line = ('space:move in the demo\'s Platformer scene, %d steps of 1/60 s: the character at (%.1f, %.1f),'
        .. ' on the ground: %s, stood on %d surfaces (tiles, slopes, steps, the one-way platform); bullets at 400 px'
        .. ' a step: %d fired, %d stopped at a wall, 0 passed\n'):format(demo.MOTION_STEPS, x, y,
        m.ground and 'yes (' .. m.ground .. ')' or 'no', surfaces, st.fired, st.stopped)
      assert.is_truthy(report:find(line, 1, true), 'expected the line: ' .. line)
    end)

  it('the well-formedness check catches broken markup', function()
    assert.is_false((wellFormed('<svg><g></svg>')))
    assert.is_false((wellFormed('<svg>')))
  end)
end)
