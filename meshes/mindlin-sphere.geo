// The bodies of edp/cattaneo-mindlin-3d.edp, one per run (-setnumber body 0 or 1): the lower
// half of a sphere of radius R centred at (0, 0, R), touching the block's top z = 0 at the
// origin, and the block [-W, W] x [-W, W] x [-D, 0] under it. half = 1: only y >= 0 (the
// symmetry plane y = 0 contains the tangential load's direction x), half = 0: the whole.
// Mesh size hc within `depth` of the contact plane z = 0 and within `zone` of the
// axis (a flat disc, not a ball: the stick/slip boundary lies on the surface and needs the
// fine size there, the elastic field below varies over the contact radius), growing with the
// distance to that disc to R/4; the block's 0.9 hc, so that its faces and the sphere's nodes
// do not match.
// Physical surfaces: 2 the plane y = 0 (half models), 3 the sphere's cut z = R (driven and
// loaded), 4 the sphere's curved surface (the contact), 5 the block's top (the contact),
// 6 its bottom (held), 7 its other sides; volume 1. Every boundary triangle is in a physical
// group (FreeFEM's gmshload3 needs the whole boundary).
SetFactory("OpenCASCADE");
DefineConstant[ body = 0, half = 1, R = 10, W = 20, D = 20, hc = 0.2, zone = 2.5, depth = 0.5 ];
e = 1e-6;
y0 = half ? 0 : -W;
If (body == 0)
  Sphere(1) = {0, 0, R, R};
  Box(2) = {-R, half ? 0 : -R, 0, 2 * R, half ? R : 2 * R, R};
  BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
  sy[] = Surface In BoundingBox{-R - e, -e, -e, R + e, e, R + e};
  If (!half)
    sy[] = {};
  EndIf
  st[] = Surface In BoundingBox{-R - e, -R - e, R - e, R + e, R + e, R + e};
  curved[] = Boundary{ Volume{3}; };
  curved[] -= {sy[], st[]};
  If (half)
    Physical Surface(2) = {sy[]};
  EndIf
  Physical Surface(3) = {st[]};
  Physical Surface(4) = {curved[]};
  Physical Volume(1) = {3};
  size = hc;
Else
  Box(1) = {-W, y0, -D, 2 * W, W - y0, D};
  sy[] = Surface In BoundingBox{-W - e, -e, -D - e, W + e, e, e};
  If (!half)
    sy[] = {};
  EndIf
  top[] = Surface In BoundingBox{-W - e, y0 - e, -e, W + e, W + e, e};
  bottom[] = Surface In BoundingBox{-W - e, y0 - e, -D - e, W + e, W + e, -D + e};
  sides[] = Boundary{ Volume{1}; };
  sides[] -= {sy[], top[], bottom[]};
  If (half)
    Physical Surface(2) = {sy[]};
  EndIf
  Physical Surface(5) = {top[]};
  Physical Surface(6) = {bottom[]};
  Physical Surface(7) = {sides[]};
  Physical Volume(1) = {1};
  size = 0.9 * hc;
EndIf
Field[1] = MathEval;
Field[1].F = Sprintf("Min(%g, %g + 0.5 * Sqrt(Max(0, Sqrt(x * x + y * y) - %g)^2 + Max(0, Abs(z) - %g)^2))",
                      R / 4, size, zone, depth);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
