--- Screen layout shared by main.lua (which draws the overlays) and the scenes (whose
--- probes must keep clear of them). Pure Lua: no `love` here.
local layout = {}

layout.WIDTH, layout.HEIGHT = 800, 600
layout.BACKGROUND = { 24, 26, 32 }   -- 0-255, opaque
layout.PANEL = { 12, 13, 17 }        -- overlay panels (opaque)
layout.TEXT = { 225, 228, 235 }
layout.TITLE = { 255, 210, 90 }
layout.ERROR = { 255, 110, 100 }
layout.LINE_HEIGHT = 15              -- LÖVE's default font is 14 px high
layout.HELP_X, layout.HELP_Y, layout.HELP_W = 8, 8, 420
layout.STATUS_H = 40                 -- two lines at the bottom of the window
layout.STATUS_LINES = 2
layout.HELP_CHARS = 56               -- the longest help line (about 7 px a character: 420 px)
layout.KEY_LINES = 2                 -- the help's last lines: the number keys and the global keys

--- The help overlay's lines for scene `index` of `list`: the scene's name, its own help
--- lines, then the keys that work everywhere (each scene's number key, H or F1, Esc), in
--- layout.KEY_LINES lines: as many as fit in each line of layout.HELP_CHARS characters, the
--- rest in the last one (an empty line when they need fewer).
---@param list table[] the scene modules, in order @param index integer
---@return string[]
function layout.helpLines(list, index)
  local scene = list[index]
  local lines = { ('Scene %d/%d: %s'):format(index, #list, scene.name) }
  for _, line in ipairs(scene.help) do lines[#lines + 1] = line end
  local keys = {}
  for i, s in ipairs(list) do keys[i] = ('%d %s'):format(i, s.name) end
  keys[#keys + 1] = 'H or F1: help  Esc: quit'
  local line, used = nil, 1
  for _, key in ipairs(keys) do
    if line and used < layout.KEY_LINES and #line + 2 + #key > layout.HELP_CHARS then
      lines[#lines + 1], line, used = line, nil, used + 1
    end
    line = line and line .. '  ' .. key or key
  end
  lines[#lines + 1] = line
  for _ = used + 1, layout.KEY_LINES do lines[#lines + 1] = '' end
  return lines
end

--- The help panel's rectangle for a scene (it depends only on its number of help lines).
---@param scene table
---@return number x, number y, number w, number h
function layout.helpRect(scene)
  local n = #scene.help + 1 + layout.KEY_LINES
  return layout.HELP_X, layout.HELP_Y, layout.HELP_W, n * layout.LINE_HEIGHT + 10
end

--- The status bar along the bottom of a w x h window.
---@param w number @param h number
---@return number x, number y, number w, number h
function layout.statusRect(w, h)
  return 0, h - layout.STATUS_H, w, layout.STATUS_H
end

--- The part of a w x h window above the status bar, where the scenes live.
---@param w number @param h number
---@return number w, number h
function layout.playfield(w, h)
  return w, h - layout.STATUS_H
end

--- Every rectangle covered by an overlay at start (help shown), as { x, y, w, h } lists.
---@param scene table @param w number @param h number
---@return table[]
function layout.reserved(scene, w, h)
  return { { layout.helpRect(scene) }, { layout.statusRect(w, h) } }
end

return layout
