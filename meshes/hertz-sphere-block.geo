// The quarter block under meshes/hertz-sphere.geo's sphere: x, y in [0, W], z in [-D, 0],
// its top touching the sphere at the origin. Mesh size 0.75 hc within `zone` of the origin,
// growing to R/4 like the sphere's: the two meshes of the contact zone do not match, and the
// block's (the master's) is the finer, since mortar multipliers on the coarser side
// oscillate less (with the block at 1.3 hc the pressure per node scattered by about ±10 %
// at hc = 0.1; docs/log.md).
// The block comes in FETI subdomains with conforming interfaces: the cube [0, c]^2 x [-c, 0]
// at the contact (c = zone) as 2 x 2 x 2 boxes, physical volumes 1-8, and the rest of the
// block, physical volume 9 (a split of the mesh by element centroids left tetrahedra
// hanging by an edge, singular subdomains).
// Physical surfaces: 1 the plane x = 0, 2 the plane y = 0, 5 the top z = 0 (the contact),
// 6 the bottom z = -D (held), 7 the free sides x = W and y = W (every boundary triangle must
// be in a physical group, or FreeFEM's mesh3 misses it).
SetFactory("OpenCASCADE");
DefineConstant[ R = 10, W = 20, D = 20, hc = 0.2, zone = 2.5 ];
c = zone;
h = c / 2;
k = 0;
For i In {0 : 1}
  For j In {0 : 1}
    For l In {0 : 1}
      k += 1;
      Box(k) = {i * h, j * h, -(l + 1) * h, h, h, h};
    EndFor
  EndFor
EndFor
Box(9) = {0, 0, -D, W, W, D};
BooleanFragments{ Volume{9}; Delete; }{ Volume{1 : 8}; Delete; }
// After the fragments the eight boxes keep their tags 1-8; the rest of the block is the
// one volume left.
all[] = Volume{:};
rest[] = all[];
rest[] -= {1 : 8};
For k In {1 : 8}
  Physical Volume(k) = {k};
EndFor
Physical Volume(9) = {rest[]};
e = 1e-6;
Physical Surface(1) = Surface In BoundingBox{-e, -e, -D - e, e, W + e, e};
Physical Surface(2) = Surface In BoundingBox{-e, -e, -D - e, W + e, e, e};
Physical Surface(5) = Surface In BoundingBox{-e, -e, -e, W + e, W + e, e};
Physical Surface(6) = Surface In BoundingBox{-e, -e, -D - e, W + e, W + e, -D + e};
Physical Surface(7) = {Surface In BoundingBox{W - e, -e, -D - e, W + e, W + e, e},
                       Surface In BoundingBox{-e, W - e, -D - e, W + e, W + e, e}};
Field[1] = MathEval;
Field[1].F = Sprintf("Min(%g, %g + 0.5 * Max(0, Sqrt(x * x + y * y + z * z) - %g))", R / 4, 0.75 * hc, zone);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
