--- The shape data contract: where a shape keeps its world-space data. This file is the only
--- place that spells a slot number; every other file reads these names.
---
--- A shape is its own world-data array (the narrow phase reads one table per shape and
--- follows no pointer). Its scalar state is there too, in numbered slots rather than named
--- fields: a LuaJIT table's hash part is a power of two of 24-byte nodes, and a shape with
--- its two dozen scalars named took a 32-node hash (768 bytes) where its own fields now fit
--- in 8. Every shape has the same header:
---
---   slot   name     meaning
---   1-4    MINX, MINY, MAXX, MAXY   axis-aligned bounds                refreshed when dirty
---   5-6    X, Y     the pose's position: the centroid (a circle's     always current: transforms
---                   centre), in world coordinates                      write it directly
---   7      R        the world radius the shape is rounded by: a        refreshed when dirty
---                   circle's radius; 0 for polygons and segments
---   8      ANGLE    the pose's angle (radians)                         always current
---   9-10   COS, SIN its cosine and sine                                always current
---   11     SCALE    the pose's uniform scale                           always current
---   12     DIRTY    true when the world data above and below is stale  (Shape:_touch)
---   13     AREA     the area, unscaled                                 set at construction
---   14     RADIUS   the largest distance from the centroid, unscaled   set at construction
---   15     SHORT    the shortest length, unscaled (limits.lua): a      set at construction
---                   polygon's shortest edge, a circle's radius, 0
---
--- A shape without vertices (a circle, a point) has those SHAPE_HEADER slots and no more: its
--- slot COUNT is nil, which is how the code that meets any shape tells it has none. Shapes
--- made of vertices (VertexShape: polygons, edges, chain segments) go on:
---
---   16     COUNT    the number of vertices, n                          set at construction
---   17     HALF     n / 2 when the shape is centrally symmetric, else 0 (VertexShape.lua)
---   18     ROUND    the rounding radius, unscaled (0: sharp)           set at construction
---   19-20  NCOS, NSIN  the COS, SIN the world normals were turned by   refreshed when dirty
---   21-23  RX, RY, RSCALE  the X, Y, SCALE of the last refresh         (false before the first)
---
--- and follow with one record of STRIDE numbers per vertex; vertex i's record starts at slot
--- base(i) = STRIDE * i + BASE and holds, at these offsets from its start:
---   VX, VY   the vertex
---   NX, NY   the unit outward normal of edge i (vertex i to vertex i + 1, wrapping)
---   D        the offset of edge i's line along that normal: dot(normal i, vertex i)
--- All refreshed when dirty. A shape with n vertices has size(n) slots.
---
--- A chain segment (base/ChainSegment.lua: an edge, two vertex records) goes on after them
--- with its neighbours' data, from slot size(2) + 1 to CHAIN_SIZE:
---   HASPREV, HASNEXT    whether it has a neighbour before p1 / after p2 (booleans)
---   CONVEX1, CONVEX2    whether the corner at p1 / p2 is convex (booleans)
---   G1X, G1Y, G2X, G2Y  the corner normals in world coordinates          refreshed when dirty
---   LG1X ... LG2Y       the same, local (unrotated)                       set at construction
---   LPREVX, LPREVY, LNEXTX, LNEXTY  the ghost vertices, local (0 when absent)
---
--- Everything else a shape keeps (its local geometry `_l`, its pose stamp `_pose`, its kind
--- `_kind`, its class's own data) is in named fields starting with `_`; a shape's integer keys
--- are strike's alone, and every other name is the game's (strike/reserved.lua).
---
--- A collider (colliders/Collider.lua) keeps its cached aggregates in its own array part
--- too, so that moving one reads and writes a few adjacent numbers instead of a dozen
--- fields spread over its hash part (valid while its flags say so; its integer keys are
--- strike's alone as well):
---
---   slot    name              meaning
---   1-4     MINX ... MAXY     the bounds of every leaf            (`_clean`)
---   5-6     X, Y              the centroid                        (`_massOK`)
---   7       CRADIUS           the radius about the centroid       (`_clean`; -1 until the
---                                                                  first getRadius)
---   8       CAREA             the area of the leaves              (`_massOK`)
---   9-10    CAX, CAY          the sums of area * centroid         (`_massOK`)
---   11-13   CLEN, CLX, CLY    edges: the sum of lengths, and of length * midpoint
---   14-15   CSX, CSY          the sum of the leaves' centroids (the mean of points)
---                             (of the sums in 9-15, a translation keeps current only those the
---                             centroid comes from: Collider.lua, shift)
---   16      CANGLE            the angle (the sum of its rotations)
---   17      CCOUNT            the number of leaves below it       (`_massOK` or `_clean`:
---                                                                  both set it)
local layout = {}

--- The bounds' slots.
layout.MINX, layout.MINY, layout.MAXX, layout.MAXY = 1, 2, 3, 4
--- The position's slots.
layout.X, layout.Y = 5, 6
--- The radius slot.
layout.R = 7
--- The pose's slots.
layout.ANGLE, layout.COS, layout.SIN, layout.SCALE, layout.DIRTY = 8, 9, 10, 11, 12
--- The unscaled sizes' slots.
layout.AREA, layout.RADIUS, layout.SHORT = 13, 14, 15
--- Number of slots every shape has.
layout.SHAPE_HEADER = 15
--- A vertex shape's own slots.
layout.COUNT, layout.HALF, layout.ROUND = 16, 17, 18
layout.NCOS, layout.NSIN, layout.RX, layout.RY, layout.RSCALE = 19, 20, 21, 22, 23
--- Number of header slots of a vertex shape (the header every shape has, then its own).
layout.HEADER = 23

--- A collider's slots (see above).
layout.CRADIUS, layout.CAREA, layout.CAX, layout.CAY = 7, 8, 9, 10
layout.CLEN, layout.CLX, layout.CLY, layout.CSX, layout.CSY = 11, 12, 13, 14, 15
layout.CANGLE, layout.CCOUNT = 16, 17
--- Number of a collider's slots.
layout.CSIZE = 17

--- A chain segment's slots, after its two vertex records (see above).
layout.HASPREV, layout.HASNEXT, layout.CONVEX1, layout.CONVEX2 = 34, 35, 36, 37
layout.G1X, layout.G1Y, layout.G2X, layout.G2Y = 38, 39, 40, 41
layout.LG1X, layout.LG1Y, layout.LG2X, layout.LG2Y = 42, 43, 44, 45
layout.LPREVX, layout.LPREVY, layout.LNEXTX, layout.LNEXTY = 46, 47, 48, 49
--- Number of a chain segment's slots.
layout.CHAIN_SIZE = 49

--- Slots per vertex record.
layout.STRIDE = 5
--- Offsets in a vertex record.
layout.VX, layout.VY, layout.NX, layout.NY, layout.D = 0, 1, 2, 3, 4
--- base(i) = STRIDE * i + BASE: vertex 1's record starts right after the header.
layout.BASE = layout.HEADER + 1 - layout.STRIDE
--- The first vertex record's slot, base(1).
layout.FIRST = layout.HEADER + 1

--- The slot where vertex i's record starts.
---@param i integer
---@return integer
function layout.base(i) return layout.STRIDE * i + layout.BASE end

--- The slot of the last vertex record's start, for a shape of n vertices: base(n).
---@param n integer
---@return integer
function layout.last(n) return layout.STRIDE * n + layout.BASE end

--- Number of array slots a shape of n vertices uses (the header alone for n = 0).
---@param n integer
---@return integer
function layout.size(n) return layout.HEADER + layout.STRIDE * n end

-- (the chain segment's slots start right after its two vertex records)
assert(layout.HASPREV == layout.size(2) + 1, 'layout.lua: the chain segment slots must follow size(2)')

return layout
