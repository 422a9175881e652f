// A quarter sphere pressed on a block (three dimensions), the solid example of ffeti-solve
// with GetDP (getdp/sphere-block.pro, docs/getdp.md) and its FreeFEM twin
// (tests/edp/sphere-block.edp). Each body is cut in two subdomains, one physical volume
// each (GetDP assembles one system per physical volume). Units mm.
// Sphere: the lower half of radius R centred at (0, 0, R), quarter x >= 0, y >= 0, touching
// the block's top z = 0 at the origin; cut at z = zc: volumes 101 (below, the contact side),
// 102. Surfaces: 1 its plane x = 0, 2 its plane y = 0, 3 the cut z = R (the load), 4 the
// spherical surface below zc (the contact), 5 the rest of its surface (free).
// Block [0, W] x [0, W] x [-D, 0], cut at x = W/2: volumes 201 (under the contact), 202.
// Surfaces: 11 top (the contact), 12 x = 0, 13 y = 0, 14 bottom, 15 x = W and y = W (free).
// Every boundary face is in a physical surface: FreeFEM's gmshload3 needs the whole boundary.
// The two bodies are built and fragmented apart, so that the sphere's lowest point and the
// block's corner at the origin stay two nodes (bodies share no node).
SetFactory("OpenCASCADE");
DefineConstant[ R = 10, W = 10, D = 5, zc = 3, hc = 0.2, zone = 2 ];
e = 1e-6;
// ---- sphere: two pieces, fragmented so that their common disc is meshed once ----
Sphere(1) = {0, 0, R, R};
Box(2) = {0, 0, 0, R, R, zc};
BooleanIntersection(10) = { Volume{1}; }{ Volume{2}; Delete; };
Box(3) = {0, 0, zc, R, R, R - zc};
BooleanIntersection(11) = { Volume{1}; Delete; }{ Volume{3}; Delete; };
BooleanFragments{ Volume{10}; Delete; }{ Volume{11}; Delete; }
low[] = Volume In BoundingBox{-e, -e, -e, R + e, R + e, zc + e};
high[] = Volume In BoundingBox{-e, -e, zc - e, R + e, R + e, R + e};
// ---- block: two boxes, fragmented likewise ----
Box(20) = {0, 0, -D, W / 2, W, D};
Box(21) = {W / 2, 0, -D, W / 2, W, D};
BooleanFragments{ Volume{20}; Delete; }{ Volume{21}; Delete; }
left[] = Volume In BoundingBox{-e, -e, -D - e, W / 2 + e, W + e, e};
right[] = Volume In BoundingBox{W / 2 - e, -e, -D - e, W + e, W + e, e};
// ---- boundary groups, found by where they lie ----
sx[] = Surface In BoundingBox{-e, -e, -e, e, R + e, R + e};
sy[] = Surface In BoundingBox{-e, -e, -e, R + e, e, R + e};
st[] = Surface In BoundingBox{-e, -e, R - e, R + e, R + e, R + e};
disc[] = Surface In BoundingBox{-e, -e, zc - e, R + e, R + e, zc + e};
contact[] = Boundary{ Volume{low[]}; };
contact[] -= {sx[], sy[], disc[]};
top[] = Surface In BoundingBox{-e, -e, -e, W + e, W + e, e};
bx[] = Surface In BoundingBox{-e, -e, -D - e, e, W + e, e};
by[] = Surface In BoundingBox{-e, -e, -D - e, W + e, e, e};
bottom[] = Surface In BoundingBox{-e, -e, -D - e, W + e, W + e, -D + e};
free[] = CombinedBoundary{ Volume{low[], high[]}; };
free[] -= {sx[], sy[], st[], contact[]};
sides[] = CombinedBoundary{ Volume{left[], right[]}; };
sides[] -= {top[], bx[], by[], bottom[]};
Physical Volume(101) = {low[]};
Physical Volume(102) = {high[]};
Physical Volume(201) = {left[]};
Physical Volume(202) = {right[]};
Physical Surface(1) = {sx[]};
Physical Surface(2) = {sy[]};
Physical Surface(3) = {st[]};
Physical Surface(4) = {contact[]};
Physical Surface(5) = {free[]};
Physical Surface(11) = {top[]};
Physical Surface(12) = {bx[]};
Physical Surface(13) = {by[]};
Physical Surface(14) = {bottom[]};
Physical Surface(15) = {sides[]};
// ---- mesh size: hc within `zone` of the contact point, growing with the distance to R/4 ----
Field[1] = MathEval;
Field[1].F = Sprintf("Min(%g, %g + 0.4 * Max(0, Sqrt(x * x + y * y + z * z) - %g))", R / 4, hc, zone);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
