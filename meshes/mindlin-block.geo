// The block under the cylinder of meshes/mindlin-cylinder.geo: [-W, W] x [-D, 0] (mm), the
// contact at the origin. Mesh size hc (mm) within `zone` mm of the contact. Labels: 11 top
// (contact), 12 right, 13 bottom, 14 left.
DefineConstant[ W = 100, D = 100, hc = 0.25, zone = 8 ];
Point(1) = {-W, 0, 0, W / 8};
Point(2) = {W, 0, 0, W / 8};
Point(3) = {W, -D, 0, W / 8};
Point(4) = {-W, -D, 0, W / 8};
Point(5) = {0, 0, 0, hc};
// Counter-clockwise, so that FreeFEM gets positive triangles.
Line(1) = {2, 5};
Line(2) = {5, 1};
Line(3) = {1, 4};
Line(4) = {4, 3};
Line(5) = {3, 2};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Field[1] = Distance;
Field[1].PointsList = {5};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hc;
Field[2].SizeMax = W / 8;
Field[2].DistMin = zone;
Field[2].DistMax = zone + W;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Physical Curve(11) = {1, 2};
Physical Curve(12) = {5};
Physical Curve(13) = {4};
Physical Curve(14) = {3};
Physical Surface(1) = {1};
