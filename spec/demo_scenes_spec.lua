-- The LÖVE demo's scenes driven in plain Lua through their input handlers, as demo/main.lua
-- drives them from LÖVE's callbacks: dragging and turning shapes, aiming rays, drawing
-- concave outlines (valid and not), walking over tile seams and chain joints, the stress
-- scene's space: its pairs, contact events and counts against a brute-force loop, and the
-- platformer's space:move: a character over tiles, slopes, stairs and a one-way platform,
-- and bullets that no thin wall lets through.
local S = require('strike')
local scenes = require('demo.scenes.list')

local W, H = 800, 600

local function sceneNamed(name)
  for _, scene in ipairs(scenes) do
    if scene.name == name then return scene end
  end
  error('no scene ' .. name)
end

-- A painter that records the names of the calls a scene's paint makes.
local function recorder()
  local calls = {}
  local painter = setmetatable({}, { __index = function(_, name)
    return function() calls[#calls + 1] = name end
  end })
  return painter, calls
end

local function countOf(list, value)
  local n = 0
  for _, v in ipairs(list) do if v == value then n = n + 1 end end
  return n
end

local function bodyNamed(state, name)
  for _, b in ipairs(state.bodies) do
    if b.name == name then return b end
  end
end

describe('demo scene: shape pairs', function()
  local scene = sceneNamed('Shape pairs')

  it('drags a body with the left button and moves it by exactly the mouse motion', function()
    local state = scene.new(S, W, H)
    local pentagon = bodyNamed(state, 'pentagon').body
    local x0, y0 = pentagon:getCentroid()
    scene.mousepressed(state, x0, y0, 1)
    scene.mousemoved(state, x0 - 30, y0 + 20, -30, 20)
    scene.mousemoved(state, x0 - 50, y0 + 10, -20, -10)
    scene.mousereleased(state, x0 - 50, y0 + 10, 1)
    scene.mousemoved(state, x0 + 100, y0 + 100, 150, 90) -- released: nothing moves
    local x1, y1 = pentagon:getCentroid()
    assert.near(x0 - 50, x1, 1e-9)
    assert.near(y0 + 10, y1, 1e-9)
  end)

  it('counts and shows the collisions, and changes the colour of the bodies that collide', function()
    local state = scene.new(S, W, H)
    local P, calls = recorder()
    scene.paint(state, P)
    local hits = #state.hits
    assert.is_true(hits >= 2)
    assert.equals(hits, countOf(calls, 'mtv'))
    assert.equals(hits, countOf(calls, 'contacts'))
    assert.equals(0, countOf(calls, 'proj'))
    local circle = bodyNamed(state, 'circle')
    assert.is_true(state.colliding[circle])
    -- drag the circle into the open: one collision fewer, and it is no longer hot
    local x, y = circle.body:getCentroid()
    scene.mousepressed(state, x, y, 1)
    scene.mousemoved(state, x + 260, y - 150)
    scene.mousereleased(state, x + 260, y - 150, 1)
    assert.equals(hits - 1, #state.hits)
    assert.is_nil(state.colliding[circle])
    assert.matches('^' .. (hits - 1) .. ' collisions', scene.status(state)[1])
  end)

  it('turns a body with the right button, the wheel and Q / E held', function()
    local state = scene.new(S, W, H)
    local rect = bodyNamed(state, 'rectangle').body
    local x, y = rect:getCentroid()
    local a0 = rect:getAngle()
    scene.mousepressed(state, x, y, 2)
    scene.mousemoved(state, x + 50, y)
    scene.mousereleased(state, x + 50, y, 2)
    assert.near(a0 + 0.5, rect:getAngle(), 1e-9)
    local cx, cy = rect:getCentroid()
    assert.near(x, cx, 1e-9) -- turned about its centroid, not moved
    assert.near(y, cy, 1e-9)
    scene.mousemoved(state, x, y)
    scene.wheelmoved(state, 0, 2)
    assert.near(a0 + 0.8, rect:getAngle(), 1e-9)
    scene.keypressed(state, 'e')
    for _ = 1, 10 do scene.update(state, 0.02) end
    scene.keyreleased(state, 'e')
    scene.update(state, 0.02)
    assert.near(a0 + 0.8 + 0.5, rect:getAngle(), 1e-9)
  end)

  it('toggles projections and normals, and resets', function()
    local state = scene.new(S, W, H)
    scene.keypressed(state, 'p')
    scene.keypressed(state, 'n')
    local P, calls = recorder()
    scene.paint(state, P)
    assert.equals(#state.hits, countOf(calls, 'proj'))
    assert.equals(0, countOf(calls, 'norms'))
    bodyNamed(state, 'hexagon').body:translate(100, 0)
    scene.keypressed(state, 'r')
    assert.same(scene.probes(scene.new(S, W, H)), scene.probes(state))
  end)
end)

describe('demo scene: rays', function()
  local scene = sceneNamed('Rays')

  it('casts a fan of rays from the mouse, more or fewer with + and -', function()
    local state = scene.new(S, W, H)
    scene.mousemoved(state, 420, 330)
    local P, calls = recorder()
    scene.paint(state, P)
    assert.equals(state.rays, countOf(calls, 'ray'))
    local rays = state.rays
    scene.keypressed(state, '+')
    assert.equals(rays + 8, state.rays)
    scene.keypressed(state, '-')
    scene.keypressed(state, '-')
    assert.equals(rays - 8, state.rays)
    assert.matches('^' .. state.rays .. ' rays from %(420, 330%): %d+ hit', scene.status(state)[1])
  end)

  it('aims one ray at a clicked target and lists its boundary crossings', function()
    local state = scene.new(S, W, H)
    local circle = state.bodies[1].body
    local cx, cy = circle:getCentroid()
    scene.mousemoved(state, cx, cy + 135)
    scene.mousepressed(state, cx, cy, 1) -- up through the circle's centre: 2 crossings, nothing else
    local P, calls = recorder()
    scene.paint(state, P)
    assert.equals(1, countOf(calls, 'ray'))
    assert.equals(2 + 1, countOf(calls, 'disc')) -- the crossings and the origin
    local status = scene.status(state)
    assert.matches('2 boundary crossings; first hit at distance 85.0', status[2])
    scene.mousepressed(state, cx, cy, 2) -- back to the fan
    assert.is_nil(state.target)
    -- the target on the origin itself: no ray, no error
    scene.mousepressed(state, cx, cy + 135, 1)
    scene.paint(state, recorder())
    assert.is_string(scene.status(state)[1])
  end)
end)

describe('demo scene: concave', function()
  local scene = sceneNamed('Concave')

  local function outline(state, points, close)
    for i = 1, #points, 2 do scene.mousepressed(state, points[i], points[i + 1], 1) end
    if close == 'right' then scene.mousepressed(state, 0, 0, 2) else scene.keypressed(state, 'return') end
  end

  it('starts with the example outline split into convex pieces', function()
    local state = scene.new(S, W, H)
    assert.is_nil(state.error)
    assert.is_true(state.poly:getShapeCount() >= 3)
    assert.matches('convex pieces', scene.status(state)[1])
  end)

  it('builds an outline clicked point by point and closed with Enter or the right button', function()
    local state = scene.new(S, W, H)
    outline(state, { 200, 200, 400, 200, 400, 260, 260, 260, 260, 400, 200, 400 }) -- an L
    assert.is_nil(state.error)
    assert.equals(2, state.poly:getShapeCount())
    assert.near(200 * 60 + 60 * 140, state.poly:getArea(), 1e-6)
    outline(state, { 500, 300, 600, 300, 550, 380 }, 'right')
    assert.equals(1, state.poly:getShapeCount())
    assert.same({}, state.draft)
  end)

  it('shows the library\'s message for an invalid outline instead of failing', function()
    local state = scene.new(S, W, H)
    outline(state, { 200, 200, 500, 400, 500, 200, 200, 400 }, 'right') -- a bow tie
    assert.is_nil(state.poly)
    assert.matches('^strike%.Concave: outline intersects itself', state.error)
    local line = scene.status(state)[1]
    assert.is_true(line.error)
    assert.equals(state.error, line.text)
    scene.paint(state, recorder()) -- the refused outline is still drawn
    -- too few points: the library says so too
    outline(state, { 100, 100, 200, 200 })
    assert.matches('^strike%.Concave: .*3', state.error)
    -- a spike (the outline folds back on itself)
    outline(state, { 100, 100, 300, 100, 200, 100, 200, 300 })
    assert.is_string(state.error)
  end)

  it('clears with C or Backspace, and brings the example back with X', function()
    local state = scene.new(S, W, H)
    scene.mousepressed(state, 100, 100, 1)
    scene.keypressed(state, 'c')
    assert.is_nil(state.poly)
    assert.same({}, state.draft)
    scene.keypressed(state, 'x')
    assert.same(scene.probes(scene.new(S, W, H)), scene.probes(state))
    scene.keypressed(state, 'backspace')
    assert.is_nil(state.poly)
    scene.keypressed(state, 'return') -- nothing to close
    assert.is_nil(state.error)
  end)
end)

describe('demo scene: terrain', function()
  local scene = sceneNamed('Terrain')
  local FLOOR = 480

  -- Hold `key` and step until body b passes x = stop (or `steps` run out); the body's x must
  -- grow every step once it moves, it must stay on the ground, and on the tiles its bottom
  -- must stay on their top.
  local function walk(state, b, key, stop, steps, sign)
    scene.keypressed(state, key)
    local px = b.body:getCentroid()
    local moved = false
    for i = 1, steps do
      scene.update(state, scene.STEP)
      local x = b.body:getCentroid()
      local x0, _, x1, bottom = b.body:getBounds()
      if moved then
        assert.is_true((x - px) * sign > 0, ('%s snagged at x = %.3f (step %d)'):format(b.name, x, i))
      end
      moved = moved or x ~= px
      assert.is_true(b.grounded, ('%s left the ground at x = %.3f (step %d)'):format(b.name, x, i))
      if x1 < 400 then -- over the tiles only
        assert.is_true(math.abs(bottom - FLOOR) < 0.5, ('%s at x = %.2f: bottom %.3f'):format(b.name, x, bottom))
      end
      px = x
      if (x - stop) * sign >= 0 then break end
      assert(x0 >= 0 and x1 <= W)
    end
    scene.keyreleased(state, key)
    return px
  end

  it('the box slides over every tile seam and chain joint to the far end without snagging', function()
    local state = scene.new(S, W, H)
    state.ball.body:translateTo(20, 462) -- out of the way, behind the box
    local x = walk(state, state.box, 'right', 760, 2000, 1)
    assert.is_true(x >= 760)
  end)

  it('and back again to the left', function()
    local state = scene.new(S, W, H)
    state.ball.body:translateTo(785, 397)
    state.box.body:translateTo(740, 397)
    for _ = 1, 30 do scene.update(state, scene.STEP) end
    local x = walk(state, state.box, 'left', 40, 2000, -1)
    assert.is_true(x <= 40)
  end)

  it('the ball crosses the tile seams too, and both come to rest on a slope without creeping', function()
    local state = scene.new(S, W, H)
    state.box.body:translateTo(30, 462)
    walk(state, state.ball, 'd', 520, 2000, 1)
    for _ = 1, 120 do scene.update(state, scene.STEP) end -- stop
    local x0, y0 = state.ball.body:getCentroid()
    for _ = 1, 240 do scene.update(state, scene.STEP) end
    local x1, y1 = state.ball.body:getCentroid()
    assert.near(x0, x1, 1e-9)
    assert.near(y0, y1, 1e-9)
    assert.is_true(state.ball.grounded)
    assert.is_true(state.ball.mtv.nx < -0.1) -- on the slope
  end)

  it('jumps from the ground and lands again; the status shows the contact normal', function()
    local state = scene.new(S, W, H)
    local _, y0 = state.box.body:getCentroid()
    scene.keypressed(state, 'up')
    scene.update(state, scene.STEP)
    scene.keyreleased(state, 'up')
    local top = y0
    for _ = 1, 240 do
      scene.update(state, scene.STEP)
      local _, y = state.box.body:getCentroid()
      top = math.min(top, y)
    end
    assert.is_true(y0 - top > 60)
    local _, y1 = state.box.body:getCentroid()
    assert.near(y0, y1, 0.5)
    assert.is_true(state.box.grounded)
    assert.matches('^box at .*on the ground: normal %(0%.00, %-1%.00%)', scene.status(state)[1])
  end)
end)

describe('demo scene: stress', function()
  local scene = sceneNamed('Stress')

  -- The colliding pairs now, by a loop over every pair of bodies (boxes first, then
  -- S.triking), as "i,j" keys of their indices in state.bodies (the order they were added
  -- to the space) into a set, and as a list in pair order.
  local function bruteForce(state)
    local bodies, boxes = state.bodies, {}
    for i, b in ipairs(bodies) do boxes[i] = { b.body:getBounds() } end
    local set, list = {}, {}
    for i = 1, #bodies do
      local p = boxes[i]
      for j = i + 1, #bodies do
        local q = boxes[j]
        if p[1] <= q[3] and q[1] <= p[3] and p[2] <= q[4] and q[2] <= p[4]
          and S.triking(bodies[i].body, bodies[j].body) then
          local key = i .. ',' .. j
          set[key] = true
          list[#list + 1] = key
        end
      end
    end
    return set, list
  end

  local function count(set, minus)
    local n = 0
    for key in pairs(set) do if not minus[key] then n = n + 1 end end
    return n
  end

  it('finds the colliding pairs through its space, as a brute-force loop does, and counts begins and ends',
    function()
      local state = scene.new(S, W, H)
      assert.equals(scene.COUNT, #state.bodies)
      assert.equals(scene.COUNT, state.space:count())
      local index = {}
      for i, b in ipairs(state.bodies) do index[b.body] = i end
      local prev = {}
      local collisions, begins, ends, stays = 0, 0, 0, 0
      for frame = 1, 60 do
        scene.move(state, 1 / 60)
        local cur, list = bruteForce(state)
        local flashBefore = {}
        for i, b in ipairs(state.bodies) do flashBefore[i] = b.flash end
        scene.collide(state)
        local s = state.stats
        local where = 'frame ' .. frame
        assert.equals(#list, s.collisions, where)
        assert.equals(count(cur, prev), s.begins, where)
        assert.equals(count(prev, cur), s.ends, where)
        -- the space's list, in its documented order: by the first body's rank, then the second's
        local got = {}
        for k = 1, s.collisions do
          local rec = state.pairs[k]
          got[k] = index[rec.a] .. ',' .. index[rec.b]
        end
        assert.same(list, got, where)
        -- yellow: the bodies of the colliding pairs; a flash starts on every body of a pair
        -- that began
        local hit, began = {}, {}
        for key in pairs(cur) do
          local i, j = key:match('^(%d+),(%d+)$')
          i, j = tonumber(i), tonumber(j)
          hit[i], hit[j] = true, true
          if not prev[key] then began[i], began[j] = true, true end
        end
        for i, b in ipairs(state.bodies) do
          assert.equals(hit[i] or false, b.hit, where .. ': body ' .. i .. ' hit')
          assert.equals(began[i] and scene.FLASH_TIME or flashBefore[i], b.flash, where .. ': body ' .. i .. ' flash')
        end
        collisions, begins, ends = collisions + s.collisions, begins + s.begins, ends + s.ends
        stays = stays + s.collisions - s.begins
        assert.is_true(s.ms >= 0)
        prev = cur
      end
      assert.is_true(collisions > 0 and begins > 0 and ends > 0)
      local lines = scene.status(state)
      assert.matches(('^%d bodies in an S%%.pace: %d colliding pairs; contacts this frame: %d began, %d ended')
        :format(scene.COUNT, state.stats.collisions, state.stats.begins, state.stats.ends), lines[1])
      assert.matches('ms/frame', lines[2])
    end)

  it('keeps every body inside the field, and + / - add bodies to the space and remove them', function()
    local state = scene.new(S, W, H)
    for _ = 1, 120 do scene.update(state, 1 / 30) end
    for _, b in ipairs(state.bodies) do
      local x0, y0, x1, y1 = b.body:getBounds()
      assert.is_true(x0 >= -1e-9 and y0 >= -1e-9 and x1 <= state.fieldW + 1e-9 and y1 <= state.fieldH + 1e-9)
    end
    scene.keypressed(state, '+')
    assert.equals(scene.COUNT + 50, #state.bodies)
    assert.equals(scene.COUNT + 50, state.space:count())
    scene.update(state, 1 / 60)
    assert.equals(scene.COUNT + 50, state.stats.bodies)
    local removed = {}
    for i = #state.bodies - 99, #state.bodies do removed[#removed + 1] = state.bodies[i].body end
    scene.keypressed(state, '-')
    scene.keypressed(state, 'kp-')
    assert.equals(scene.COUNT - 50, #state.bodies)
    assert.equals(scene.COUNT - 50, state.space:count())
    for _, body in ipairs(removed) do assert.is_false(state.space:has(body)) end
    scene.update(state, 1 / 60) -- (the removed bodies' contacts end here)
    for k = 1, state.stats.collisions do
      assert.is_true(state.space:has(state.pairs[k].a) and state.space:has(state.pairs[k].b))
    end
    for _ = 1, 100 do scene.keypressed(state, '-') end
    assert.equals(50, #state.bodies)
    assert.equals(50, state.space:count())
  end)

  it('B shows and hides the broadphase (S.howSpace on screen; its lines kept clear by the probes)', function()
    local state = scene.new(S, W, H)
    for _ = 1, 10 do scene.update(state, 1 / 60) end
    local P, calls = recorder()
    scene.paint(state, P)
    assert.equals(0, countOf(calls, 'space'))
    local plain = scene.probes(state)
    scene.keypressed(state, 'b')
    P, calls = recorder()
    scene.paint(state, P)
    assert.equals(1, countOf(calls, 'space'))
    -- the probe model draws the tree's boxes too: every probe keeps clear of their lines
    local margin = require('demo.util.probe').MARGIN
    local boxes = {}
    state.space:_eachNode(function(_, x0, y0, x1, y1) boxes[#boxes + 1] = { x0, y0, x1, y1 } end)
    assert.is_true(#boxes >= scene.COUNT)
    local probes = scene.probes(state)
    assert.is_true(#probes >= 5)
    for _, p in ipairs(probes) do
      local px, py = p.x + 0.5, p.y + 0.5
      for _, r in ipairs(boxes) do
        local d -- from the pixel's centre to the box's outline
        if px >= r[1] and px <= r[3] and py >= r[2] and py <= r[4] then
          d = math.min(px - r[1], r[3] - px, py - r[2], r[4] - py)
        else
          d = math.sqrt(math.max(r[1] - px, 0, px - r[3]) ^ 2 + math.max(r[2] - py, 0, py - r[4]) ^ 2)
        end
        assert.is_true(d >= margin, ('probe %s at (%d, %d): %.2f px from a box'):format(p.what, p.x, p.y, d))
      end
    end
    assert.are_not.same(plain, probes)
    scene.keypressed(state, 'b')
    P, calls = recorder()
    scene.paint(state, P)
    assert.equals(0, countOf(calls, 'space'))
  end)
end)

describe('demo scene: platformer', function()
  local scene = sceneNamed('Platformer')

  it('walks the scripted route over every kind of ground, never ending a step inside the level', function()
    local state = scene.new(S, W, H)
    assert.is_true(state.grounded)
    assert.equals('tile 1', state.names[state.ground])
    local onSlope = 0
    for i = 1, 1200 do
      local px = state.character:getCentroid()
      scene.step(state, scene.STEP)
      local x = state.character:getCentroid()
      local where = ('step %d, x = %.3f'):format(i, x)
      -- nothing of the level overlaps it but the one-way platform, while it jumps up through it
      local recs, n = state.space:check(state.character)
      for k = 1, n do
        local name = state.names[recs[k].b]
        assert.is_true(name == 'one-way platform', where .. ': inside ' .. name)
      end
      assert.is_true(x >= 10 - 1e-9 and x <= W - 10 + 1e-9, where)
      -- on a slope (the option `slope`): on the ground at every step, walking at full speed
      -- across it, up or down (`snap`: no hops down)
      if (x > 270 and x < 350) or (x > 450 and x < 490) then
        assert.is_true(state.grounded, where .. ': in the air over a slope')
        assert.near(scene.STEP * 150, math.abs(x - px), 1e-9, where)
        onSlope = onSlope + 1
      end
    end
    assert.is_true(onSlope > 100)
    for _, name in ipairs({ 'tile 1', 'tile 8', 'slope 26.6°', 'plateau 1', 'slope 45°', 'one-way platform',
      'tile 12' }) do
      assert.is_true(state.touched[name], 'never stood on ' .. name)
    end
    -- every step of the stairs, up (`step`: 6-px risers, up to 10 climbed) and down
    for k = 1, 6 do assert.is_true(state.touched['step ' .. k], 'never stood on step ' .. k) end
  end)

  it('jumps up through the one-way platform from below and lands on it from above', function()
    local state = scene.new(S, W, H)
    local P = scene.PLATFORM
    local below, above, landed = false, false, nil
    for i = 1, 60 do
      scene.step(state, scene.STEP)
      local x0, y0, x1, y1 = state.character:getBounds()
      if x1 > P[1] and x0 < P[3] then
        if y0 > P[2] then below = true end              -- wholly below the platform
        if below and y1 < P[2] then above = true end    -- then wholly above: it passed through
      end
      if above and state.grounded and state.names[state.ground] == 'one-way platform' then
        landed = i
        assert.near(P[2], y1, 1e-3) -- standing on it
        break
      end
    end
    assert.is_true(below and above, 'never passed up through the platform')
    assert.is_truthy(landed, 'never landed on the platform')
    -- it stands there: solid from above
    local _, y = state.character:getCentroid()
    scene.step(state, scene.STEP)
    local _, y2 = state.character:getCentroid()
    assert.near(y, y2, 1e-9)
    assert.is_true(state.grounded)
    assert.matches('on ground: yes %(one%-way platform%)', scene.status(state)[1])
  end)

  it('stops every bullet at its wall (1 to 4 px and an edge, 400 px a step), then takes it out of the space',
    function()
      local state = scene.new(S, W, H)
      local fixed = state.space:count() - #state.bullets
      local perLane = {}
      for i = 1, 300 do
        scene.step(state, scene.STEP)
        local st = state.stats
        assert.equals(0, st.passed, 'step ' .. i)
        for _, b in ipairs(state.bullets) do
          local x = b.body:getCentroid()
          local face = scene.LANES[b.lane].x
          assert.is_true(x + scene.BULLET_R <= face, ('step %d: a bullet past the wall at x = %d'):format(i, face))
          if b.hold == scene.HOLD then -- stopped this step: at the wall, a skin short
            assert.near(face, x + scene.BULLET_R, 1e-3)
            perLane[b.lane] = (perLane[b.lane] or 0) + 1
          end
        end
        assert.equals(st.fired, st.stopped + st.inFlight, 'step ' .. i)
        -- bullets stay scene.HOLD steps once stopped, then leave the space
        assert.equals(fixed + #state.bullets, state.space:count())
        assert.is_true(#state.bullets <= scene.HOLD / scene.FIRE_EVERY + 2)
      end
      for lane = 1, #scene.LANES do assert.is_true((perLane[lane] or 0) >= 25, 'lane ' .. lane) end
      assert.matches('bullets stopped: ' .. state.stats.stopped .. ', passed: 0$', scene.status(state)[2])
    end)

  it('gives the character to the arrow keys (the script stops), and P gives it back', function()
    local state = scene.new(S, W, H)
    scene.keypressed(state, 'left')
    assert.is_false(state.script)
    for _ = 1, 10 do scene.update(state, scene.STEP) end
    scene.keyreleased(state, 'left')
    local x = state.character:getCentroid()
    assert.near(scene.START_X - 25, x, 1e-9) -- 10 steps of 2.5 px, to the left
    scene.keypressed(state, 'up')
    scene.update(state, scene.STEP)
    scene.keyreleased(state, 'up')
    assert.is_false(state.grounded)
    assert.matches('your keys$', scene.status(state)[1])
    for _ = 1, 120 do scene.update(state, scene.STEP) end
    assert.is_true(state.grounded) -- landed again, where it jumped
    assert.near(scene.START_X - 25, (state.character:getCentroid()), 1e-9)
    scene.keypressed(state, 'p')
    assert.is_true(state.script)
    scene.update(state, scene.STEP)
    assert.near(scene.START_X - 25 + 2.5, (state.character:getCentroid()), 1e-9)
  end)

  it('B shows and hides the broadphase (S.howSpace)', function()
    local state = scene.new(S, W, H)
    local P, calls = recorder()
    scene.paint(state, P)
    assert.equals(0, countOf(calls, 'space'))
    scene.keypressed(state, 'b')
    P, calls = recorder()
    scene.paint(state, P)
    assert.equals(1, countOf(calls, 'space'))
  end)
end)

describe('demo scenes: R', function()
  for _, name in ipairs({ 'Shape pairs', 'Terrain', 'Stress', 'Platformer' }) do
    it(('resets %s in place to its initial state, keeping the clock main.lua set'):format(name), function()
      local scene = sceneNamed(name)
      local state = scene.new(S, W, H)
      local clock = function() return 0 end
      state.clock = clock
      scene.keypressed(state, 'right')
      for _ = 1, 30 do scene.update(state, 1 / 30) end
      scene.keypressed(state, 'r')
      local fresh = scene.new(S, W, H)
      assert.equals(clock, state.clock)
      assert.same(scene.probes(fresh), scene.probes(state))
      assert.same(scene.status(fresh), scene.status(state))
    end)
  end
end)

describe('demo scene: tiled level', function()
  local scene = sceneNamed('Tiled level')
  local map = require('demo.maps.level')

  it('loads demo/maps/level.lua, a map in the shape of Tiled\'s Lua export, through S.tiled', function()
    assert.same({ '5.1', 'orthogonal', 'lua' }, { map.luaversion, map.orientation, map.layers[1].encoding })
    local state = scene.new(S, W, H)
    local level, space = state.level, state.space
    assert.equals(26, #level.bodies)
    -- the ground: one body of its 84 connected tiles (hill included), holes and all
    local ground = level.bodies[3]
    local o = level.objectOf[ground]
    assert.same({ 'ground', 84, 9 }, { o.tile.properties.kind, o.tiles, ground:getShapeCount() })
    assert.is_true(ground:containsPoint(4 * 32 + 16, 14 * 32 + 16))
    assert.is_false(ground:containsPoint(4 * 32 + 16, 15 * 32 + 16)) -- (a hole)
    assert.is_false(ground:containsPoint(4 * 32 + 16, 15 * 32)) -- (the hole's edge)
    assert.is_true(ground:containsPoint(2 * 32 + 16, 15 * 32)) -- (the face between two of its rectangles)
    -- six slopes, the three on the way down flipped: their high side on the left
    local up, down = 0, 0
    for _, b in ipairs(level.bodies) do
      local t = level.objectOf[b]
      if t.tile and t.tile.properties.kind == 'slope' then
        local x0, y0, x1 = b:getBounds()
        if b:containsPoint(x1 - 2, y0 + 4) then up = up + 1 end
        if b:containsPoint(x0 + 2, y0 + 4) then down = down + 1 end
      end
    end
    assert.same({ 3, 3 }, { up, down })
    -- coins: sensors on the layer 'coin'
    assert.equals(12, #state.coins)
    for _, c in ipairs(state.coins) do
      local layer, _, _, sensor = space:get(c)
      assert.same({ 'coin', true }, { layer, sensor })
    end
    assert.is_true(state.grounded)
  end)

  it('walks the level with space:move: onto the one-way platform, over the hill, the boulder and the step, and back,'
    .. ' never ending a step inside the level, picking up coins', function()
    local state = scene.new(S, W, H)
    local names = {}
    for _, b in ipairs(state.level.bodies) do
      local o = state.level.objectOf[b]
      names[b] = o.tiles and (o.tile and o.tile.properties.kind) or o.name
    end
    local stood, right, back = {}, false, false
    for i = 1, 1200 do
      scene.step(state, scene.STEP)
      local x = state.character:getCentroid()
      local recs, n = state.space:check(state.character)
      for k = 1, n do
        assert.equals('platform', names[recs[k].b], ('step %d: inside %s'):format(i, tostring(names[recs[k].b])))
      end
      if state.ground then stood[names[state.ground]] = true end
      if x >= 740 then right = true end
      if right and x <= 40 then back = true end
    end
    assert.is_true(right and back)
    for _, name in ipairs({ 'platform', 'slope', 'ground' }) do
      assert.is_true(stood[name] == true, 'never stood on ' .. name)
    end
    assert.is_true(state.picked >= 8, state.picked .. ' coins')
    local left = 0
    for _, c in ipairs(state.coins) do if state.space:has(c) then left = left + 1 end end
    assert.equals(12 - state.picked, left)
    assert.matches('coins picked up: ' .. state.picked, scene.status(state)[1])
  end)
end)
