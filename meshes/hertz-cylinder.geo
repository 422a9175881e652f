// Half of a cylinder of radius R (mm) resting on y = 0 at the origin, x >= 0; the cut
// through its centre (y = R) carries the load. Mesh size hc (mm) within 10 mm of the contact, growing
// away from it. Labels: 1 arc (contact), 2 top (load), 3 symmetry x = 0.
DefineConstant[ R = 50, hc = 1 ];
Point(1) = {0, 0, 0, hc};
Point(2) = {0, R, 0, R / 8};
Point(3) = {R, R, 0, R / 8};
Circle(1) = {1, 2, 3};
Line(2) = {3, 2};
Line(3) = {2, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hc;
Field[2].SizeMax = R / 8;
Field[2].DistMin = 10;  // the contact zone (half-width about 6 mm) stays at size hc
Field[2].DistMax = R;
Background Field = 2;
Physical Curve(1) = {1};
Physical Curve(2) = {2};
Physical Curve(3) = {3};
Physical Surface(1) = {1};
