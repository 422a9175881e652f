// The lower half of a cylinder of radius R (mm) resting on y = 0 at the origin, both sides
// (a tangential load breaks the symmetry of meshes/hertz-cylinder.geo). The cut through its
// centre (y = R) carries the loads. Mesh size hc (mm) within `zone` mm of the contact,
// growing away from it. Labels: 1 arc (contact), 2 top cut (loads).
DefineConstant[ R = 50, hc = 0.25, zone = 8 ];
Point(1) = {0, 0, 0, hc};
Point(2) = {0, R, 0, R / 8};
Point(3) = {R, R, 0, R / 8};
Point(4) = {-R, R, 0, R / 8};
Circle(1) = {4, 2, 1};
Circle(2) = {1, 2, 3};
Line(3) = {3, 4};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hc;
Field[2].SizeMax = R / 8;
Field[2].DistMin = zone;
Field[2].DistMax = zone + R;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Physical Curve(1) = {1, 2};
Physical Curve(2) = {3};
Physical Surface(1) = {1};
