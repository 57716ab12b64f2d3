-- The headless demo (examples/demo.lua, `make demo`): its report and its SVG picture.
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
    assert.matches('first hit L block', report)
    assert.is_true(summary.collisions >= 4)
    local svg = read(path)
    assert.matches('^<%?xml', svg)
    assert(wellFormed(svg))
    assert.equals(1, count(svg, '<svg '))
    assert.equals(summary.shapes, count(svg, 'class="shape"'))
    assert.equals(summary.collisions, count(svg, 'class="mtv"'))
    assert.equals(summary.contacts, count(svg, 'class="contact"'))
    assert.equals(1, count(svg, 'class="ray"'))
    -- the arrows are drawn longer than the MTVs: both the picture and the report say so
    assert.equals(1, count(svg, 'class="legend"'))
    assert.matches('<text class="legend"[^>]*>[^<]*drawn 4× their length', svg)
    assert.matches('MTV arrow is drawn 4 times its length', report)
    local shapes = 0
    for _, item in ipairs(demo.scene()) do shapes = shapes + item.body:getShapeCount() end
    assert.equals(shapes, summary.shapes)
  end)

  it('the well-formedness check catches broken markup', function()
    assert.is_false((wellFormed('<svg><g></svg>')))
    assert.is_false((wellFormed('<svg>')))
  end)
end)
