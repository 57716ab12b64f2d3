-- strike: zero warnings, the common subset of Lua 5.1-5.4.
std = 'min'
max_line_length = 120
ignore = { '212/self' } -- methods keep `self` even when a subclass needs no state
files['spec'] = { std = 'min+busted' }
files['.busted'] = { std = 'min' }
exclude_files = { '.git' }
-- The LÖVE demo (love demo): LÖVE's globals, and only its callbacks defined.
files['demo/'] = { std = 'min+love' }
-- The example games (love examples/<name>), likewise. examples/demo.lua is plain Lua.
files['examples/platformer/'] = { std = 'min+love' }
files['examples/shooter/'] = { std = 'min+love' }
files['examples/tiled/'] = { std = 'min+love' }
-- bench/lovephysics: a LÖVE program (Box2D through love.physics) that bench/space.lua runs.
files['bench/lovephysics/'] = { std = 'min+love' }
