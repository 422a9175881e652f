// Half of the block under the cylinder: [0, W] x [-D, 0] (mm), contact at the origin.
// Mesh size hc (mm) within 10 mm of the contact. Labels: 11 top (contact), 12 right, 13 bottom,
// 14 symmetry x = 0.
DefineConstant[ W = 100, D = 100, hc = 1 ];
Point(1) = {0, 0, 0, hc};
Point(2) = {W, 0, 0, W / 8};
Point(3) = {W, -D, 0, W / 8};
Point(4) = {0, -D, 0, W / 8};
// Counter-clockwise, so that FreeFEM gets positive triangles.
Line(1) = {2, 1};
Line(2) = {3, 2};
Line(3) = {4, 3};
Line(4) = {1, 4};
Curve Loop(1) = {4, 3, 2, 1};
Plane Surface(1) = {1};
Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hc;
Field[2].SizeMax = W / 8;
Field[2].DistMin = 10;  // the contact zone (half-width about 6 mm) stays at size hc
Field[2].DistMax = W;
Background Field = 2;
Physical Curve(11) = {1};
Physical Curve(12) = {2};
Physical Curve(13) = {3};
Physical Curve(14) = {4};
Physical Surface(1) = {1};
