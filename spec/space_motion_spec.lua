-- Space:cast, Space:move and Space:addResponse: the first hit of a move, move-and-slide with
-- its responses, no tunnelling at any speed, no ghost collisions at seams, the character
-- options (slopes, snapping, steps), errors at the caller's line and no garbage per move.
-- Hand-worked cases.
local S = require('strike')
local expect = require('spec.helpers.expect')
local alloc = require('spec.helpers.alloc')
local PRNG = require('spec.helpers.prng')
local raisesAt, near = expect.raisesAt, expect.near
local H, T = S.hapes, S.trikers
local rad = math.rad
local unpack = table.unpack or unpack -- luacheck: ignore 113 143

-- The gap a stop leaves (docs/moving.md, "Moving bodies in a space", The stop and the skin):
-- half the skin, Space.SKIN times the body's radius.
local function skin(body) return S.pace().SKIN * body:getRadius() / 2 end

describe('S.pace motion', function()
  setup(alloc.jitOff)
  teardown(alloc.jitOn)

  describe('cast', function()
    it('gives the first body hit, with S.weep\'s hit and the body', function()
      local sp = S.pace()
      local far = sp:add(H.Rectangle(100, 0, 10, 40))
      local near_ = sp:add(H.Rectangle(50, 0, 10, 40))
      local box = H.Rectangle(0, 0, 10, 10) -- not in the space
      local h = sp:cast(box, 100, 0)
      -- the box's right face x = 5 meets near's left face x = 45 after 40 of 100
      assert.equal(near_, h.body)
      near(h.t, 0.4)
      near(h.nx, -1)
      near(h.ny, 0)
      near(h.x, 45)
      near(h.y, 0)
      assert.is_false(h.overlapping)
      -- a filter, then the far one: its face x = 95 after 90
      local h2 = sp:cast(box, 100, 0, function(b) return b ~= near_ end)
      assert.equal(far, h2.body)
      near(h2.t, 0.9)
      assert.is_false(sp:cast(box, 30, 0))
      assert.is_false(sp:cast(box, 0, 100))
    end)

    it('fills `out`, follows layers, masks and sensors, and breaks ties by the order of adding', function()
      local sp = S.pace()
      local a = sp:add(H.Rectangle(50, -10, 10, 10), { layer = 'wall' })
      local b = sp:add(H.Rectangle(50, 10, 10, 10), { layer = 'wall' })
      sp:add(H.Rectangle(30, 0, 10, 50), { sensor = true })
      local mover = sp:add(H.Rectangle(0, 0, 10, 30), { layer = 'player', mask = { 'wall' } })
      local out = {}
      -- a and b are met at the same time, by the same face: a was added first
      assert.equal(out, sp:cast(mover, 100, 0, nil, out))
      assert.equal(a, out.body)
      near(out.t, 0.4)
      sp:set(mover, { mask = { 'enemy' } })
      assert.is_false(sp:cast(mover, 100, 0, nil, out))
      sp:set(mover, { mask = false })
      assert.equal(b, sp:cast(mover, 100, 0, { mask = { 'nothing' } }) == false and b or b)
      assert.equal(a, sp:cast(mover, 100, 0, function(o) return o == a or o == b end).body)
    end)

    it('reports a body it starts in as an overlap, and allocates nothing with `out`', function()
      local sp = S.pace()
      local wall = sp:add(H.Rectangle(10, 0, 10, 10))
      local box = sp:add(H.Rectangle(3, 0, 10, 10)) -- overlapping by 3
      local h = sp:cast(box, 5, 0)
      assert.equal(wall, h.body)
      assert.is_true(h.overlapping)
      assert.equal(0, h.t)
      near(h.nx, -1)
      local out, other = {}, H.Circle(-100, 0, 5)
      local kb = alloc.kbPer(function() sp:cast(other, 200, 0, nil, out) end, 10000)
      alloc.nothingPerCall(kb, 'Space:cast with out')
    end)
  end)

  describe('move', function()
    it('slides along what it meets: the motion into the surface is dropped', function()
      local sp = S.pace()
      local wall = sp:add(H.Rectangle(50, 0, 10, 200))
      local box = sp:add(H.Rectangle(0, 0, 10, 10))
      local x, y, cols, n = sp:move(box, 100, 30)
      -- the leg from (0, 0) to (100, 30) touches x = 40 at t = 0.4, then slides to y = 30
      local s = skin(box)
      assert.equal(1, n)
      near(x, 40 - s * 100 / 100 / 1, 1e-9)
      near(y, 30, 1e-9)
      local c = cols[1]
      assert.equal(wall, c.other)
      assert.equal('slide', c.type)
      near(c.t, 0.4)
      near(c.nx, -1)
      near(c.ny, 0)
      near(c.touchX, 40 - s, 1e-9)
      near(c.touchY, 12 - 0.3 * s, 1e-9)
      near(c.x, 45)
      assert.is_false(c.overlapping)
      local bx, by = box:getCentroid()
      near(bx, x, 0)
      near(by, y, 0)
    end)

    it('touch stops, cross passes and is reported once, bounce reflects, nil ignores', function()
      local sp = S.pace()
      local w1 = sp:add(H.Rectangle(50, 0, 10, 200))
      local w2 = sp:add(H.Rectangle(80, 0, 10, 200))
      local box = sp:add(H.Rectangle(0, 0, 10, 10))
      local s = skin(box)
      local x, y, cols, n = sp:move(box, 100, 0, function() return 'touch' end)
      near(x, 40 - s, 1e-9)
      near(y, 0)
      assert.equal(1, n)
      assert.equal('touch', cols[1].type)
      box:translateTo(0, 0)
      x, y, cols, n = sp:move(box, 100, 0, function(_, o) return o == w1 and 'cross' or 'touch' end)
      near(y, 0)
      assert.equal(2, n)
      assert.equal(w1, cols[1].other)
      assert.equal('cross', cols[1].type)
      assert.equal(w2, cols[2].other)
      near(x, 70 - s, 1e-9)
      box:translateTo(0, 0)
      x, y, cols, n = sp:move(box, 60, 20, function() return 'bounce' end)
      -- touches x = 40 at t = 2/3 (y = 40/3), then the 20 left over reflects: x = 40 - 20
      assert.equal(1, n)
      assert.equal('bounce', cols[1].type)
      near(x, 40 - 20, 1e-4)
      near(y, 20, 1e-4)
      box:translateTo(0, 0)
      x, y, cols, n = sp:move(box, 100, 0, function() return nil end)
      assert.equal(0, n)
      near(x, 100)
      near(y, 0)
      assert.equal(0, #cols)
    end)

    it('runs responses added with addResponse, and refuses bad ones at the caller\'s line', function()
      local sp = S.pace()
      sp:add(H.Rectangle(50, 0, 10, 200))
      local box = sp:add(H.Rectangle(0, 0, 10, 10))
      local seen
      sp:addResponse('half', function(space, col, x, y, gx, gy)
        seen = { space, col.type, x, y, gx, gy }
        return col.touchX, col.touchY, col.touchX, col.touchY - 7
      end)
      local x, y = sp:move(box, 100, 0, function() return 'half' end)
      assert.equal(sp, seen[1])
      assert.equal('half', seen[2])
      near(seen[3], 0)
      near(seen[5], 100)
      near(y, -7, 1e-9)
      near(x, 40 - skin(box), 1e-9)
      raisesAt(function() sp:addResponse(1, print) end, 'strike.Space:addResponse: argument 1 (name) must be a string')
      raisesAt(function() sp:addResponse('slide', print) end, 'strike.Space:addResponse: "slide" is a built-in')
      raisesAt(function() sp:addResponse('x', 5) end, 'strike.Space:addResponse: argument 2 must be a function')
      sp:addResponse('bad', function() return 1, 2, 0 / 0, 3 end)
      box:translateTo(0, 0)
      raisesAt(function() sp:move(box, 100, 0, function() return 'bad' end) end,
        'strike.Space:move: response "bad" must return four finite numbers')
      box:translateTo(0, 0)
      raisesAt(function() sp:move(box, 100, 0, function() return 'glide' end) end,
        'strike.Space:move: the filter returned string "glide", which is not a response')
      -- (after those errors, a move meets the wall again)
      box:translateTo(0, 0)
      local _, _, _, n = sp:move(box, 100, 0)
      assert.equal(1, n)
    end)

    it('refuses bad arguments at the caller\'s line', function()
      local sp = S.pace()
      local box = sp:add(H.Rectangle(0, 0, 10, 10))
      local loose = H.Rectangle(0, 0, 10, 10)
      raisesAt(function() sp:move(loose, 1, 1) end, 'strike.Space:move: argument 1 (a shape) is not in this space')
      raisesAt(function() sp:move(nil, 1, 1) end, 'strike.Space:move: argument 1 must be a strike collider or shape')
      raisesAt(function() sp:move(box, 0 / 0, 1) end, 'strike.Space:move: argument 2 (goalX) must be a finite number')
      raisesAt(function() sp:move(box, 1, 1 / 0) end, 'strike.Space:move: argument 3 (goalY) must be a finite number')
      raisesAt(function() sp:move(box, 1, 1, 'slide') end, 'strike.Space:move: argument 4 (filter) must be a function')
      raisesAt(function() sp:move(box, 1, 1, nil, 3) end, 'strike.Space:move: argument 5 (options) must be a table')
      raisesAt(function() sp:move(box, 1, 1, nil, { slopes = 1 }) end, 'strike.Space:move: unknown option string')
      raisesAt(function() sp:move(box, 1, 1, nil, { slope = 2 }) end, 'strike.Space:move: slope must be an angle')
      raisesAt(function() sp:move(box, 1, 1, nil, { snap = -1 }) end, 'strike.Space:move: snap must be a length')
      raisesAt(function() sp:move(box, 1, 1, nil, { step = 'x' }) end, 'strike.Space:move: step must be a length')
      raisesAt(function() sp:move(box, 1, 1, nil, { up = { 0, 0 } }) end, 'strike.Space:move: up must be a direction')
      raisesAt(function() sp.move(5, box, 1, 1) end, 'strike.Space:move')
      raisesAt(function() sp:cast(nil, 1, 1) end, 'strike.Space:cast: argument 1 must be a strike collider or shape')
      raisesAt(function() sp:cast(box, 'a', 1) end, 'strike.Space:cast: argument 2 (dx) must be a finite number')
      raisesAt(function() sp:cast(box, 1, 0 / 0) end, 'strike.Space:cast: argument 3 (dy) must be a finite number')
      raisesAt(function() sp:cast(box, 1, 1, 5) end, 'strike.Space:cast: argument 4')
      raisesAt(function() sp:cast(box, 1, 1, nil, 5) end, 'strike.Space:cast: argument 5 (out) must be a plain table')
    end)

    it('allocates nothing per move, its list and records reused', function()
      local sp = S.pace()
      sp:add(H.Rectangle(50, 0, 10, 200))
      sp:add(H.Rectangle(0, 50, 200, 10))
      local box = sp:add(H.Circle(30, 30, 5))
      local _, _, first = sp:move(box, 100, 100)
      local kb = alloc.kbPer(function()
        box:translateTo(30, 30)
        local _, _, cols, n = sp:move(box, 100, 100)
        assert(cols == first and n == 2)
      end, 10000)
      alloc.nothingPerCall(kb, 'Space:move')
      -- moves that meet two bodies, then none: the records of the longer list are kept for the
      -- next one
      local odd = false
      kb = alloc.kbPer(function()
        odd = not odd
        box:translateTo(30, 30)
        local _, _, cols, n = sp:move(box, odd and 100 or 30, odd and 100 or 20)
        assert(cols == first and n == (odd and 2 or 0) and #cols == n)
      end, 10000)
      alloc.nothingPerCall(kb, 'Space:move, two collisions then none')
    end)

    it('stops in a corner it slides into, and comes back to a body it slid along', function()
      -- A V of two walls 4 wide, their centre lines from (-50, 13.7) and (50, 13.7) down to
      -- the apex (0, 57 + 50 cos 30 deg) = (0, 100.30127): a circle r = 5 dropped in touches
      -- both inner faces (2 from the centre lines) with its centre on the axis, at a distance
      -- (5 + 2) / sin 30 deg = 14 above the apex: y = 86.30127. It slides down the first wall
      -- into the second, whose slide would turn it back into the first: it stops there, after
      -- two collisions (without the corner rule it bounced between them 25 times).
      local sp = S.pace()
      local a = sp:add(H.Rectangle(-25, 57, 4, 100, rad(-30)))
      local b = sp:add(H.Rectangle(25, 57, 4, 100, rad(30)))
      local ball = sp:add(H.Circle(3, 0, 5))
      local x, y, cols, n = sp:move(ball, 3, 200)
      assert.equal(2, n)
      assert.equal(b, cols[1].other)
      assert.equal(a, cols[2].other)
      near(x, 0, 1e-4)
      near(y, 100.30127018922193 - 14, 1e-4)
      assert.is_false(S.triking(ball, a))
      assert.is_false(S.triking(ball, b))
      -- a box pushed down and sideways onto a floor and against a tilted wall: the slide along
      -- the wall turns down into the floor it slid along first, and the floor stops it again
      sp = S.pace()
      local floor = sp:add(H.Rectangle(0, 110, 400, 20)) -- top y = 100
      local wall = sp:add(H.Rectangle(60, 60, 10, 200, rad(20)))
      local box = sp:add(H.Rectangle(0, 90, 10, 10))
      sp:move(box, 100, 120)
      assert.is_false(S.triking(box, floor))
      assert.is_false(S.triking(box, wall))
    end)

    it('meets a body it starts in only when the move goes further in', function()
      -- the box spans x [-5, 5] and the wall x [3, 13] (3 deep, MTV along x): moving right goes
      -- further in: an overlapping collision at t = 0, normal (-1, 0), and the slide keeps only
      -- the motion along y; moving left (out) or along y meets nothing
      local sp = S.pace()
      local wall = sp:add(H.Rectangle(8, 0, 10, 100))
      local box = sp:add(H.Rectangle(0, 0, 10, 10))
      local x, y, cols, n = sp:move(box, 10, 4)
      assert.equal(1, n)
      assert.equal(wall, cols[1].other)
      assert.is_true(cols[1].overlapping)
      assert.equal(0, cols[1].t)
      near(cols[1].nx, -1)
      near(x, 0)
      near(y, 4)
      local x2, y2, _, n2 = sp:move(box, -10, 4)
      assert.equal(0, n2)
      near(x2, -10)
      near(y2, 4)
      box:translateTo(0, 0)
      local x3, y3, _, n3 = sp:move(box, 0, 20)
      assert.equal(0, n3)
      near(x3, 0)
      near(y3, 20)
    end)

    it('sees bodies moved, added or removed between moves (its candidates are kept only while none is)',
      function()
        local sp = S.pace()
        local box = sp:add(H.Rectangle(0, 0, 10, 10))
        local far = sp:add(H.Rectangle(500, 0, 10, 10))
        -- (the candidates are kept for this move's box padded by the box's radius and the
        -- move's length: x from about -14 to 16, where the next move stays)
        local x = sp:move(box, 2, 0)
        near(x, 2)
        far:translateTo(15, 0) -- now in the way: its left face at x = 10
        local _, _, cols, n = sp:move(box, 8, 0)
        assert.equal(1, n)
        assert.equal(far, cols[1].other)
        near(box:getCentroid(), 5, 1e-4)
        sp:remove(far)
        x = sp:move(box, 12, 0)
        near(x, 12)
        local new = sp:add(H.Rectangle(25, 0, 10, 10)) -- left face at x = 20
        _, _, cols, n = sp:move(box, 20, 0)
        assert.equal(1, n)
        assert.equal(new, cols[1].other)
        near(box:getCentroid(), 15, 1e-4)
      end)

    it('two bodies moved in turn meet each other (each one\'s moves keep the candidates)', function()
      -- a at x = 0 and b at x = 40, 10 wide: each moves 3 toward the other in turn, a first.
      -- After 5 turns each (a at 15, b at 25) their faces touch at x = 20; from then on each
      -- move meets the other and stops a skin short: they never overlap.
      local sp = S.pace()
      local a = sp:add(H.Rectangle(0, 0, 10, 10))
      local b = sp:add(H.Rectangle(40, 0, 10, 10))
      local met = 0
      for _ = 1, 10 do
        local ax, ay = a:getCentroid()
        local _, _, cols, n = sp:move(a, ax + 3, ay)
        if n > 0 and cols[1].other == b then met = met + 1 end
        assert.is_false(S.triking(a, b))
        local bx, by = b:getCentroid()
        _, _, cols, n = sp:move(b, bx - 3, by)
        if n > 0 and cols[1].other == a then met = met + 1 end
        assert.is_false(S.triking(a, b))
      end
      assert(met >= 10, 'met ' .. met)
      near(b:getCentroid() - a:getCentroid(), 10, 1e-4)
    end)

    it('gives the same answers when its filter casts, sweeps and moves other bodies meanwhile', function()
      -- a box walking right with `step` into a ledge it climbs, on a floor; a filter that, at
      -- every candidate, casts and moves a far body (with other options) and runs S.weep
      local function run(nested)
        local sp = S.pace()
        sp:add(H.Rectangle(0, 110, 400, 20))
        sp:add(H.Rectangle(300, 95, 200, 10))
        local far = sp:add(H.Circle(5000, 5000, 3))
        sp:add(H.Rectangle(5050, 5000, 10, 100))
        local box = sp:add(H.Rectangle(100, 89, 20, 20))
        local out = {}
        local filter = nested and function()
          sp:cast(far, 100, 0, nil, out)
          local fx, fy = far:getCentroid()
          sp:move(far, fx + 60, fy + 3, nil, { slope = 0.1, snap = 1 })
          far:translateTo(5000, 5000)
          S.weep(far, 100, 0, box)
          return 'slide'
        end or nil
        local trace = {}
        for _ = 1, 50 do
          local cx, cy = box:getCentroid()
          local x, y, cols, n = sp:move(box, cx + 3, cy + 1, filter, { step = 12, snap = 4 })
          trace[#trace + 1] = ('%.12g %.12g %d'):format(x, y, n)
          for i = 1, n do trace[#trace + 1] = ('%.12g %.12g'):format(cols[i].nx, cols[i].ny) end
        end
        return table.concat(trace, '\n'), box
      end
      local plain, box1 = run(false)
      local nested = run(true)
      assert.equal(plain, nested)
      local x, y = box1:getCentroid()
      near(x, 250, 1e-3) -- (150 across, over the ledge from x = 200: on top, y = 80)
      near(y, 80, 1e-3)
    end)

    it('moves a sensor straight to its goal, and nothing stops at a sensor', function()
      local sp = S.pace()
      sp:add(H.Rectangle(50, 0, 10, 200), { sensor = true })
      local box = sp:add(H.Rectangle(0, 0, 10, 10))
      local x, _, _, n = sp:move(box, 100, 0)
      assert.equal(0, n)
      near(x, 100)
      local ghost = sp:add(H.Rectangle(0, 100, 10, 10), { sensor = true })
      sp:add(H.Rectangle(50, 100, 10, 10))
      x = sp:move(ghost, 100, 100)
      near(x, 100)
    end)
  end)

  describe('no tunnelling', function()
    it('bullets at 1 to 10,000 px a move never pass a 1 px wall, an edge or a chain', function()
      local rng = PRNG.new(PRNG.seedFromEnv(12))
      local sp = S.pace()
      local walls = {
        sp:add(H.Rectangle(1000.5, 0, 1, 2e6)),                   -- x from 1000 to 1001
        sp:add(H.Edge(1000, -1e6, 1000, 1e6)),
        sp:add(T.Chain(1000, 1e6, 1000, -1e6)),                  -- free side x < 1000 (LÖVE: left of travel)
      }
      for w = 1, 3 do
        for other = 1, 3 do if other ~= w then sp:set(walls[other], { layer = 'off' }) end end
        sp:set(walls[w], { layer = 'default' })
        for _, speed in ipairs({ 1, 3, 10, 77, 1000, 10000 }) do
          for _ = 1, 30 do
            local b = rng:next() < 0.5 and H.Circle(0, 0, 2) or H.Rectangle(0, 0, 2, 3, rng:range(0, 3))
            local x0 = 1000 - 2 - speed * rng:next() - 3
            b:translateTo(x0, rng:range(-500, 500))
            sp:add(b, { mask = { 'default' } })
            local a = rng:range(-1, 1)
            local x
            for _ = 1, 3 do
              local cx, cy = b:getCentroid()
              x = sp:move(b, cx + speed * math.cos(a), cy + speed * math.sin(a), function() return 'touch' end)
            end
            assert(x < 1000, ('wall %d: a bullet at %g px a move crossed to x = %.17g'):format(w, speed, x))
            sp:remove(b)
          end
        end
      end
    end)
  end)

  describe('ghost-free', function()
    for _, scale in ipairs({ 1, 1000 }) do
      it(('a box and a capsule slide along 100 touching tiles without stopping (scale %g)'):format(scale), function()
        for _, kind in ipairs({ 'box', 'capsule' }) do
          local sp = S.pace()
          for i = 0, 99 do sp:add(H.Rectangle((i * 16 + 8) * scale, 108 * scale, 16 * scale, 16 * scale)) end
          local body = kind == 'box' and H.Rectangle(10 * scale, 90 * scale, 10 * scale, 10 * scale)
            or H.Capsule(10 * scale, 80 * scale, 10 * scale, 30 * scale)
          sp:add(body)
          for f = 1, 300 do
            local cx, cy = body:getCentroid()
            local x = sp:move(body, cx + 5 * scale, cy + 1 * scale)
            -- every move goes the whole 5 across: no seam stops or deflects it
            if f > 1 then near(x - cx, 5 * scale, 1e-9 * scale, kind .. ' frame ' .. f) end
          end
          local _, y = body:getCentroid()
          near(y, (kind == 'box' and 95 or 85) * scale, 1e-4 * scale)
        end
      end)

      it(('into an inner corner, a box stops at both walls and nowhere else (scale %g)'):format(scale), function()
        local sp = S.pace()
        for i = 0, 9 do sp:add(H.Rectangle((i * 16 + 8) * scale, 108 * scale, 16 * scale, 16 * scale)) end
        for j = 0, 9 do sp:add(H.Rectangle(168 * scale, (92 - j * 16) * scale, 16 * scale, 16 * scale)) end
        local box = sp:add(H.Rectangle(100 * scale, 50 * scale, 10 * scale, 10 * scale))
        for _ = 1, 60 do
          local cx, cy = box:getCentroid()
          sp:move(box, cx + 3 * scale, cy + 3 * scale)
        end
        local x, y = box:getCentroid()
        near(x, 155 * scale, 1e-5 * scale)
        near(y, 95 * scale, 1e-5 * scale)
      end)
    end

    it('a box landing exactly on the seam of two tiles takes the face, not the second tile\'s corner', function()
      -- tiles 16 wide with tops at y = 100; the box's bottom-right corner lands on the seam
      -- (16, 100) halfway through the move (4, 12): centre (11, 95). The second tile meets it
      -- corner to corner (either of its faces would do), the first face to face: the face
      -- wins, and the box slides on along the floor to x = 13.
      local sp = S.pace()
      sp:add(H.Rectangle(8, 108, 16, 16))
      sp:add(H.Rectangle(24, 108, 16, 16))
      local box = sp:add(H.Rectangle(9, 89, 10, 10))
      local x, y, cols, n = sp:move(box, 13, 101)
      assert.equal(1, n)
      near(cols[1].ny, -1)
      near(x, 13, 1e-9)
      near(y, 95, 1e-4)
    end)

    it('an exact corner-to-corner hit takes the normal the move grazes most', function()
      -- box A's bottom-right corner meets box B's top-left corner (16, 100) at t = 0.5: any
      -- normal between B's two faces is right; steep moves get B's side, shallow ones its top
      local b = H.Rectangle(24, 108, 16, 16)
      local h = S.weep(H.Rectangle(9, 89, 10, 10), 4, 12, b)
      near(h.t, 0.5)
      near(h.nx, -1)
      near(h.ny, 0)
      h = S.weep(H.Rectangle(5, 93, 10, 10), 12, 4, b)
      near(h.t, 0.5)
      near(h.nx, 0)
      near(h.ny, -1)
    end)

    for _, scale in ipairs({ 1, 1000 }) do
      it(('a box and a capsule walk along a chain with bumps at their full speed across (scale %g)'):format(scale),
        function()
          for _, kind in ipairs({ 'box', 'capsule' }) do
            local sp = S.pace()
            local pts = {}
            for i = 0, 60 do
              pts[#pts + 1] = i * 10 * scale
              pts[#pts + 1] = (100 + ((i % 4 == 1) and -2 or 0)) * scale -- small bumps, 11 degrees
            end
            sp:add(T.Chain(unpack(pts)))
            local body = kind == 'box' and H.Rectangle(20 * scale, 80 * scale, 10 * scale, 10 * scale)
              or H.Capsule(20 * scale, 70 * scale, 10 * scale, 30 * scale)
            sp:add(body)
            local opts = { slope = rad(45), snap = 4 * scale }
            for f = 1, 150 do
              local cx, cy = body:getCentroid()
              local x, _, _, n = sp:move(body, cx + 3 * scale, cy + 1 * scale, nil, opts)
              if f > 20 then
                near(x - cx, 3 * scale, 1e-9 * scale, kind .. ' frame ' .. f)
                assert(n > 0, kind .. ' frame ' .. f .. ': off the ground')
              end
            end
          end
        end)
    end
  end)

  describe('characters', function()
    -- A slope of 26.6 degrees (1 in 2) from (0, 300) up to (400, 100), solid below.
    local function slopeWorld()
      local sp = S.pace()
      sp:add(H.ConvexPolygon(0, 300, 400, 100, 400, 300))
      local box = sp:add(H.Rectangle(200, 150, 20, 20))
      return sp, box
    end

    it('without options a box slides down a slope under gravity; with `slope` it stays', function()
      local sp, box = slopeWorld()
      for _ = 1, 300 do
        local cx, cy = box:getCentroid()
        sp:move(box, cx, cy + 2)
      end
      local x = box:getCentroid()
      assert(x < 100, 'slid down')
      sp, box = slopeWorld()
      for _ = 1, 40 do -- fall onto the slope
        local cx, cy = box:getCentroid()
        sp:move(box, cx, cy + 2, nil, { slope = rad(50) })
      end
      local x0, y0 = box:getCentroid()
      for _ = 1, 300 do
        local cx, cy = box:getCentroid()
        sp:move(box, cx, cy + 2, nil, { slope = rad(50) })
      end
      local x1, y1 = box:getCentroid()
      near(x1, x0, 1e-9)
      near(y1, y0, 1e-9)
      -- too steep a slope for the option: it slides
      for _ = 1, 100 do
        local cx, cy = box:getCentroid()
        sp:move(box, cx, cy + 2, nil, { slope = rad(20) })
      end
      assert(box:getCentroid() < x0 - 10, 'a slope steeper than `slope` is not walkable')
    end)

    it('with `snap` a box walks down a slope touching it every move; without, it hops', function()
      for _, snap in ipairs({ false, true }) do
        local sp, box = slopeWorld()
        local opts = { slope = rad(50), snap = snap and 4 or nil }
        for _ = 1, 40 do
          local cx, cy = box:getCentroid()
          sp:move(box, cx, cy + 2, nil, opts)
        end
        local air = 0
        for _ = 1, 40 do
          local cx, cy = box:getCentroid()
          local _, _, _, n = sp:move(box, cx - 3, cy + 1, nil, opts)
          if n == 0 then air = air + 1 end
        end
        if snap then assert.equal(0, air) else assert(air > 10, 'hops: ' .. air) end
      end
    end)

    it('a one-way platform (a chain segment) lets a jump through from below, or fall back', function()
      -- the platform y = 100 from x = 0 to 200 (solid from above), a floor at y = 240 below.
      -- A capsule 44 tall jumping at 300 px/s under 1500 px/s^2 rises 30 px: its centroid
      -- passes the platform but not its feet; it falls back onto the floor (centroid 218). A
      -- jump at 600 px/s rises 120 px: it clears the platform and lands on it (centroid 78).
      -- (the same for a box 20 x 44)
      for _, jump in ipairs({ { 300, 218, H.Capsule }, { 600, 78, H.Capsule }, { 300, 218, H.Rectangle },
        { 600, 78, H.Rectangle } }) do
        local sp = S.pace()
        sp:add(T.Chain(0, 100, 200, 100))
        sp:add(H.Rectangle(100, 250, 400, 20))
        local c = sp:add(jump[3](100, 125, 20, 44))
        local vy = -jump[1]
        for _ = 1, 120 do
          vy = vy + 25
          local x, y = c:getCentroid()
          local _, _, cols, n = sp:move(c, x, y + vy / 60, nil, { slope = rad(50), snap = 4 })
          for i = 1, n do if cols[i].ny < -0.7 then vy = 0 end end
        end
        local _, y = c:getCentroid()
        near(y, jump[2], 1e-3)
      end
    end)

    it('with `step` a box climbs a ledge up to that high, and no higher', function()
      local function run(step, height)
        local sp = S.pace()
        sp:add(H.Rectangle(0, 110, 400, 20)) -- floor, top y = 100
        sp:add(H.Rectangle(300, 100 - height / 2, 200, height)) -- the ledge, from x = 200
        local box = sp:add(H.Rectangle(100, 90 - 1e-3, 20, 20))
        for _ = 1, 60 do
          local cx, cy = box:getCentroid()
          sp:move(box, cx + 3, cy + 1, nil, { step = step, snap = 4 })
        end
        return box:getCentroid()
      end
      local x, y = run(12, 10)
      near(x, 280, 1e-3)
      near(y, 80, 1e-3)
      x, y = run(6, 10)
      near(x, 190, 1e-3)
      near(y, 90, 1e-3)
      x = run(12, 14)
      near(x, 190, 1e-3)
    end)
  end)
end)
