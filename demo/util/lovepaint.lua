--- The LÖVE painter: what the scenes' paint functions draw with on screen. The same calls
--- go to the probe model (util/probe.lua), which records their geometry instead, so the
--- screenshot probes always agree with what is drawn. This file touches `love` only
--- inside its methods, so requiring it works in plain Lua.
local geom = require((...):match('^(.-)[^%.]+$') .. 'geom')

local Painter = {}
Painter.__index = Painter

--- A painter drawing with love.graphics and strike's S.how* helpers.
---@param S table strike
function Painter.new(S) return setmetatable({ S = S }, Painter) end

local function colour(rgb, alpha)
  love.graphics.setColor(rgb[1] / 255, rgb[2] / 255, rgb[3] / 255, alpha or 1)
end

--- Fill every leaf of a body in an opaque colour (edges as 3-px lines). `label` names it
--- for the probes; unused here.
function Painter:fill(body, rgb, label) -- luacheck: ignore 212/label
  colour(rgb)
  love.graphics.setLineWidth(3)
  body:draw('fill')
  love.graphics.setLineWidth(1)
end

--- Outline every leaf of a body, 1 px.
function Painter:outline(body, rgb)
  colour(rgb)
  body:draw('line')
end

function Painter:line(x1, y1, x2, y2, rgb, width)
  colour(rgb)
  love.graphics.setLineWidth(width or 1)
  love.graphics.line(x1, y1, x2, y2)
  love.graphics.setLineWidth(1)
end

function Painter:disc(x, y, r, rgb)
  colour(rgb)
  love.graphics.circle('fill', x, y, r)
end

function Painter:arrow(x1, y1, x2, y2, rgb, width)
  local ax, ay, bx, by = geom.arrowHead(x1, y1, x2, y2)
  colour(rgb)
  love.graphics.setLineWidth(width or 1)
  love.graphics.line(x1, y1, x2, y2)
  love.graphics.line(ax, ay, x2, y2, bx, by)
  love.graphics.setLineWidth(1)
end

-- strike's debug helpers, as they are.
function Painter:mtv(mtv) self.S.howMTV(mtv) end
function Painter:norms(body, len) self.S.howNorms(body, len) end
function Painter:proj(mtv) self.S.howProj(mtv) end
function Painter:contacts(contacts, len) self.S.howContacts(contacts, len) end
function Painter:ray(body, x, y, dx, dy, maxDistance) return self.S.howRay(body, x, y, dx, dy, maxDistance) end

--- A space (S.pace) as S.howSpace draws it: its bodies outlined in colour rgb, then its
--- broadphase's boxes (in S.howSpace's own light blue).
function Painter:space(space, rgb)
  colour(rgb)
  self.S.howSpace(space)
end

return Painter
