-- strike as a LuaRocks rock, for `luarocks make` in this repository (README, "Install").
-- `make test` checks it (tools/rockspec-check.sh): `luarocks lint`, then `luarocks make` into a
-- temporary tree and `require 'strike'` from it under every Lua VM.
--
-- The version is "scm": the rock is whatever is checked out, not a release (there is no tag
-- or tarball; strike/init.lua's _VERSION names the version of the code).
package = "strike"
version = "scm-1"

-- LuaRocks requires source.url (a string; `luarocks lint` checks nothing more), but this
-- repository has no public address yet. `luarocks make`, the one way to build this rock for
-- now, never reads it: it builds the directory it runs in, which is what "." says. `luarocks
-- build` or `install` of this file fail ("Couldn't extract archive"): there is nothing to fetch.
-- Publishing the rock means putting the public repository's address here (with a tag, in a
-- versioned rockspec).
source = {
   url = ".",
}

description = {
   summary = "2D collision detection for LÖVE and any Lua: convex shapes, colliders, SAT",
   detailed = [[
strike tests convex shapes against each other with the separating axis theorem and tells you
how to push them apart (a minimum translation vector), with contact points, rays and compound
bodies (colliders). Pure Lua, no dependencies, no globals; LÖVE is needed only for drawing.]],
   license = "MIT",
}

dependencies = {
   "lua >= 5.1, < 5.5",
}

-- Every file under strike/, by its module name: tools/rockspec-check.sh fails when a file is
-- missing here (a module added later without this line), or when the module name does not
-- match the path. strike.lua at the repository's root is not part of the rock: it only helps
-- `require 'strike'` inside the repository on Lua 5.1, and a rocks tree's path finds
-- strike/init.lua by itself.
build = {
   type = "builtin",
   modules = {
      ["strike.base.ChainSegment"] = "strike/base/ChainSegment.lua",
      ["strike.base.Shape"] = "strike/base/Shape.lua",
      ["strike.base.VertexShape"] = "strike/base/VertexShape.lua",
      ["strike.base.layout"] = "strike/base/layout.lua",
      ["strike.check"] = "strike/check.lua",
      ["strike.class"] = "strike/class.lua",
      ["strike.collide.MTV"] = "strike/collide/MTV.lua",
      ["strike.collide.args"] = "strike/collide/args.lua",
      ["strike.collide.chain"] = "strike/collide/chain.lua",
      ["strike.collide.compound"] = "strike/collide/compound.lua",
      ["strike.collide.contact"] = "strike/collide/contact.lua",
      ["strike.collide.dispatch"] = "strike/collide/dispatch.lua",
      ["strike.collide.kinds"] = "strike/collide/kinds.lua",
      ["strike.collide.outline"] = "strike/collide/outline.lua",
      ["strike.collide.ray"] = "strike/collide/ray.lua",
      ["strike.collide.rounded"] = "strike/collide/rounded.lua",
      ["strike.collide.sat"] = "strike/collide/sat.lua",
      ["strike.colliders.Capsule"] = "strike/colliders/Capsule.lua",
      ["strike.colliders.Chain"] = "strike/colliders/Chain.lua",
      ["strike.colliders.Collider"] = "strike/colliders/Collider.lua",
      ["strike.colliders.Concave"] = "strike/colliders/Concave.lua",
      ["strike.colliders.single"] = "strike/colliders/single.lua",
      ["strike.compat"] = "strike/compat.lua",
      ["strike.draw"] = "strike/draw.lua",
      ["strike.geometry.decompose"] = "strike/geometry/decompose.lua",
      ["strike.geometry.hull"] = "strike/geometry/hull.lua",
      ["strike.geometry.polygon"] = "strike/geometry/polygon.lua",
      ["strike"] = "strike/init.lua",
      ["strike.limits"] = "strike/limits.lua",
      ["strike.motion.kernels"] = "strike/motion/kernels.lua",
      ["strike.motion.separation"] = "strike/motion/separation.lua",
      ["strike.motion.sweep"] = "strike/motion/sweep.lua",
      ["strike.registry"] = "strike/registry.lua",
      ["strike.reserved"] = "strike/reserved.lua",
      ["strike.shapes.Capsule"] = "strike/shapes/Capsule.lua",
      ["strike.shapes.Circle"] = "strike/shapes/Circle.lua",
      ["strike.shapes.ConvexPolygon"] = "strike/shapes/ConvexPolygon.lua",
      ["strike.shapes.Edge"] = "strike/shapes/Edge.lua",
      ["strike.shapes.Ellipse"] = "strike/shapes/Ellipse.lua",
      ["strike.shapes.Point"] = "strike/shapes/Point.lua",
      ["strike.shapes.Rectangle"] = "strike/shapes/Rectangle.lua",
      ["strike.space.Space"] = "strike/space/Space.lua",
      ["strike.space.filter"] = "strike/space/filter.lua",
      ["strike.space.motion"] = "strike/space/motion.lua",
      ["strike.space.tree"] = "strike/space/tree.lua",
      ["strike.shapes.RegularPolygon"] = "strike/shapes/RegularPolygon.lua",
      ["strike.tiled.level"] = "strike/tiled/level.lua",
      ["strike.tiled.map"] = "strike/tiled/map.lua",
      ["strike.tiled.merge"] = "strike/tiled/merge.lua",
      ["strike.tiled.shapes"] = "strike/tiled/shapes.lua",
      ["strike.vec"] = "strike/vec.lua",
   },
}
