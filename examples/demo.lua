--- The headless demo: a small scene, its collisions, MTVs and contact points, then the same
--- bodies in an S.pace with a rectangle query and a ray cast through the space, reported as
--- a table and drawn to an SVG file; then space:move, in the LÖVE demo's Platformer scene run
--- without LÖVE (a character walking a level, bullets stopped by thin walls). Plain Lua,
--- every VM:
---   lua examples/demo.lua [path.svg]        (or `make demo`)
--- As a module, `require('examples.demo').run(path, write)` builds the same scene, writes
--- the SVG to `path` and sends the report, line by line, to `write` (default: io.write).
package.path = './?.lua;./?/init.lua;' .. package.path
local S = require('strike')
local H, T = S.hapes, S.trikers

local demo = {}

--- The scene: named bodies, in drawing order.
---@return table[] list of { name =, body = }
function demo.scene()
  return {
    { name = 'floor', body = T.Collider(H.Rectangle(200, 380, 300, 40), H.Rectangle(500, 380, 300, 40)) },
    { name = 'crate', body = T.Rectangle(180, 338, 60, 50) },
    { name = 'tilted crate', body = T.Rectangle(420, 330, 60, 60, 0.6) },
    { name = 'ball', body = T.Circle(560, 338, 26) },
    { name = 'L block', body = T.Concave(80, 120, 200, 120, 200, 160, 120, 160, 120, 260, 80, 260) },
    { name = 'capsule', body = T.Capsule(185, 230, 40, 110, 0.4) },
    { name = 'hexagon', body = T.RegularPolygon(330, 200, 6, 50, 0.2) },
    { name = 'pentagon', body = T.RegularPolygon(400, 170, 5, 45) },
    { name = 'hill', body = T.Chain(600, 260, 660, 220, 720, 240, 780, 200) },
    { name = 'pebble', body = T.Circle(700, 222, 14) },
  }
end

--- The space's rectangle query: min corner x, y, width, height (as getBbox). It lies in the
--- L block's notch: the L's bounding box overlaps it, the L does not.
demo.QUERY = { 130, 170, 250, 30 }
--- The ray cast through the space: origin x, y and direction dx, dy (from the top left,
--- across the scene).
demo.RAY = { 20, 40, 1, 0.45 }
--- The steps of 1/60 s the Platformer scene (demo/scenes/platformer.lua) runs for the report:
--- its scripted walk there and back, over the one-way platform, the slopes and the stairs.
demo.MOTION_STEPS = 1200

local function fmt(v) return ('%.1f'):format(v) end

-- The picture draws each MTV arrow this many times longer than the MTV, so that shallow
-- overlaps show; the report and the picture's legend say so.
local ARROW_SCALE = 4

-- The SVG elements of one body.
local function bodySVG(out, body, colour)
  for s in body:elems() do
    if s:getKind() == 'circle' then
      local x, y = s:getCentroid()
      out[#out + 1] = ('<circle class="shape" cx="%s" cy="%s" r="%s" fill="%s" fill-opacity="0.35" stroke="%s"/>')
        :format(fmt(x), fmt(y), fmt(s:getRadius()), colour, colour)
    else
      local v, n = s:getVertices()
      local pts = {}
      for i = 1, n do pts[i] = fmt(v[2 * i - 1]) .. ',' .. fmt(v[2 * i]) end
      local r = s.getRounding and s:getRounding() or 0
      if n == 2 and r > 0 then -- a capsule: its core segment swept by a disc of radius r
        out[#out + 1] = ('<polyline class="shape" points="%s" fill="none" stroke="%s" stroke-opacity="0.35"'
          .. ' stroke-width="%s" stroke-linecap="round"/>'):format(table.concat(pts, ' '), colour, fmt(2 * r))
      elseif n == 2 then
        out[#out + 1] = ('<polyline class="shape" points="%s" fill="none" stroke="%s" stroke-width="3"/>')
          :format(table.concat(pts, ' '), colour)
      else
        out[#out + 1] = ('<polygon class="shape" points="%s" fill="%s" fill-opacity="0.35" stroke="%s"/>')
          :format(table.concat(pts, ' '), colour, colour)
      end
    end
  end
end

local COLOURS = { '#7a8a99', '#d98c3f', '#c9663d', '#3f7fd9', '#8f5fc9', '#3fb58f', '#d9b23f', '#c93f6f',
  '#5f8f3f', '#3fa9c9' }

--- Build the scene, report it through `write` and draw it to the SVG file at `path`.
---@param path string @param write function|nil
---@return table summary { pairs = n, collisions = n, contacts = n, shapes = n, query = { names }, rayHit =
---  name or nil, ray = { name =, distance =, x =, y =, nx =, ny = } or nil, motion = { x =, y =, ground =
---  name or nil, surfaces = n, fired = n, stopped = n, passed = n } }
function demo.run(path, write)
  write = write or io.write
  local scene = demo.scene()
  local svg = { '<?xml version="1.0" encoding="UTF-8"?>',
    '<svg xmlns="http://www.w3.org/2000/svg" width="840" height="440" viewBox="0 0 840 440">',
    '<defs><marker id="arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="6" markerHeight="6"'
      .. ' orient="auto"><path d="M0,0 L10,5 L0,10 z" fill="#e02020"/></marker></defs>',
    '<rect width="840" height="440" fill="#fbfaf7"/>' }
  local summary = { pairs = 0, collisions = 0, contacts = 0, shapes = 0 }
  for i, item in ipairs(scene) do
    bodySVG(svg, item.body, COLOURS[i])
    summary.shapes = summary.shapes + item.body:getShapeCount()
  end
  write(('%-14s %-14s %-9s %-18s %-7s %s\n'):format('first', 'second', 'collides', 'MTV (x, y)', 'depth',
    'contact points'))
  for i = 1, #scene do
    for j = i + 1, #scene do
      local a, b = scene[i], scene[j]
      if S.aabb(a.body, b.body) then
        summary.pairs = summary.pairs + 1
        local m = S.triking(a.body, b.body)
        if m then
          summary.collisions = summary.collisions + 1
          local c = S.ite(m)
          local pts = {}
          for k = 1, c.count do
            pts[k] = ('(%s, %s)'):format(fmt(c[k].x), fmt(c[k].y))
            summary.contacts = summary.contacts + 1
            svg[#svg + 1] = ('<circle class="contact" cx="%s" cy="%s" r="4" fill="#20a040"/>')
              :format(fmt(c[k].x), fmt(c[k].y))
          end
          local x, y = m.collidedShape:getCentroid()
          svg[#svg + 1] = ('<line class="mtv" x1="%s" y1="%s" x2="%s" y2="%s" stroke="#e02020" stroke-width="2"'
            .. ' marker-end="url(#arrow)"/>')
            :format(fmt(x), fmt(y), fmt(x + m.x * ARROW_SCALE), fmt(y + m.y * ARROW_SCALE))
          write(('%-14s %-14s %-9s %-18s %-7s %s\n'):format(a.name, b.name, 'yes',
            ('(%s, %s)'):format(fmt(m.x), fmt(m.y)), fmt(m.depth), table.concat(pts, ' ')))
        else
          write(('%-14s %-14s %-9s\n'):format(a.name, b.name, 'no'))
        end
      end
    end
  end
  -- the same bodies in a space: which of them overlap a rectangle, and which one a ray hits
  -- first (the space's queries test the exact shapes, through its broadphase)
  local space = S.pace()
  local nameOf = {}
  for _, item in ipairs(scene) do
    space:add(item.body)
    nameOf[item.body] = item.name
  end
  local qx, qy, qw, qh = demo.QUERY[1], demo.QUERY[2], demo.QUERY[3], demo.QUERY[4]
  local found, n = space:queryRect(qx, qy, qw, qh)
  summary.query = {}
  local isFound, boxOnly = {}, {}
  for i = 1, n do
    summary.query[i] = nameOf[found[i]]
    isFound[found[i]] = true
  end
  for _, item in ipairs(scene) do -- (bodies whose bounding box alone overlaps the rectangle)
    local x0, y0, x1, y1 = item.body:getBounds()
    if not isFound[item.body] and x0 < qx + qw and x1 > qx and y0 < qy + qh and y1 > qy then
      boxOnly[#boxOnly + 1] = item.name
    end
  end
  write(('space:queryRect(%s, %s, %s, %s) over the %d bodies in an S.pace: %d found: %s\n'):format(qx, qy, qw, qh,
    space:count(), n, n > 0 and table.concat(summary.query, ', ') or 'none'))
  if #boxOnly > 0 then
    write(('  (exact shapes: the bounding box of %s overlaps the rectangle, the shape does not)\n')
      :format(table.concat(boxOnly, ', ')))
  end
  svg[#svg + 1] = ('<rect class="query" x="%s" y="%s" width="%s" height="%s" fill="#2060e0" fill-opacity="0.08"'
    .. ' stroke="#2060e0" stroke-dasharray="5 3"/>'):format(qx, qy, qw, qh)
  local ox, oy, dx, dy = demo.RAY[1], demo.RAY[2], demo.RAY[3], demo.RAY[4]
  local body, d, hx, hy, nx, ny = space:rayCast(ox, oy, dx, dy)
  if body then
    summary.rayHit = nameOf[body]
    summary.ray = { name = nameOf[body], distance = d, x = hx, y = hy, nx = nx, ny = ny }
    write(('space:rayCast from (%s, %s) along (%s, %s): first hit %s at (%s, %s), distance %s, normal (%.2f, %.2f)\n')
      :format(ox, oy, dx, dy, nameOf[body], fmt(hx), fmt(hy), fmt(d), nx, ny))
    svg[#svg + 1] = ('<line class="ray" x1="%s" y1="%s" x2="%s" y2="%s" stroke="#c020c0" stroke-dasharray="6 4"/>')
      :format(ox, oy, fmt(hx), fmt(hy))
    svg[#svg + 1] = ('<circle class="hit" cx="%s" cy="%s" r="5" fill="#c020c0"/>'):format(fmt(hx), fmt(hy))
    svg[#svg + 1] = ('<line class="normal" x1="%s" y1="%s" x2="%s" y2="%s" stroke="#c020c0" stroke-width="2"/>')
      :format(fmt(hx), fmt(hy), fmt(hx + nx * 20), fmt(hy + ny * 20))
  else
    write(('space:rayCast from (%s, %s) along (%s, %s): no hit\n'):format(ox, oy, dx, dy))
  end
  -- space:move: the LÖVE demo's Platformer scene, stepped without LÖVE
  local platformer = require('demo.scenes.platformer')
  local state = platformer.new(S, 800, 600)
  for _ = 1, demo.MOTION_STEPS do platformer.step(state, platformer.STEP) end
  local cx, cy = state.character:getCentroid()
  local surfaces = 0
  for _ in pairs(state.touched) do surfaces = surfaces + 1 end
  local st = state.stats
  summary.motion = { x = cx, y = cy, ground = state.grounded and state.names[state.ground] or nil,
    surfaces = surfaces, fired = st.fired, stopped = st.stopped, passed = st.passed }
  write(('space:move in the demo\'s Platformer scene, %d steps of 1/60 s: the character at (%s, %s), on the'
    .. ' ground: %s, stood on %d surfaces (tiles, slopes, steps, the one-way platform); bullets at %d px a step:'
    .. ' %d fired, %d stopped at a wall, %d passed\n'):format(demo.MOTION_STEPS, fmt(cx), fmt(cy),
    state.grounded and ('yes (%s)'):format(state.names[state.ground]) or 'no', surfaces, platformer.BULLET_SPEED,
    st.fired, st.stopped, st.passed))
  svg[#svg + 1] = ('<text class="legend" x="12" y="428" font-family="sans-serif" font-size="12"'
    .. ' fill="#333">Red: MTVs, drawn %d× their length (true values in the table). Green: contacts.'
    .. ' Blue: space:queryRect. Magenta: space:rayCast.</text>'):format(ARROW_SCALE)
  svg[#svg + 1] = '</svg>'
  local f = assert(io.open(path, 'w'))
  f:write(table.concat(svg, '\n'), '\n')
  f:close()
  write(('%d pairs tested, %d collisions, %d contact points; picture written to %s\n'):format(summary.pairs,
    summary.collisions, summary.contacts, path))
  write(('(in the picture, each MTV arrow is drawn %d times its length; the MTVs and depths above'
    .. ' are the true ones)\n'):format(ARROW_SCALE))
  return summary
end

if ... == nil or ... == arg[1] then -- run as a script (not required as a module)
  demo.run(arg[1] or 'strike-demo.svg')
end

return demo
