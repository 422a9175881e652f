// The Hertz scene of hertz-cylinder.geo and hertz-block.geo in one model, each body cut
// into subdomains by physical surfaces (GetDP assembles one system per physical surface;
// getdp/hertz.pro, docs/getdp.md). Same dimensions, mesh size hc (mm) within 10 mm of the
// contact point, growing away from it. Units mm.
// Cylinder (half, x >= 0, radius R, resting on y = 0 at the origin), cut along the radius
// at 45 degrees: surfaces 101 (contact side), 102. Curves: 1 contact arc (x <= R/4),
// 2 top (the load), 3 symmetry x = 0, 4 rest of the arc.
// Block [0, W] x [-D, 0], cut at x = W/2 and y = -D/2: surfaces 201 (under the contact),
// 202, 203, 204. Curves: 11 top (contact), 12 right, 13 bottom, 14 symmetry x = 0.
DefineConstant[ R = 50, W = 100, D = 100, hc = 1 ];
far = R / 8;
s = Sqrt(R^2 - (R / 4)^2);
// ---- cylinder ----
Point(1) = {0, 0, 0, hc};
Point(2) = {0, R, 0, far};
Point(3) = {R, R, 0, far};
Point(4) = {R / 4, R - s, 0, hc};
Point(5) = {R * Sin(Pi / 4), R - R * Cos(Pi / 4), 0, far};
Circle(1) = {1, 2, 4};
Circle(2) = {4, 2, 5};
Circle(3) = {5, 2, 3};
Line(4) = {3, 2};
Line(5) = {2, 1};
Line(6) = {2, 5};  // the cut
Curve Loop(1) = {1, 2, -6, 5};
Plane Surface(1) = {1};
Curve Loop(2) = {3, 4, 6};
Plane Surface(2) = {2};
// ---- block ----
Point(11) = {0, 0, 0, hc};
Point(12) = {W / 2, 0, 0, far};
Point(13) = {W, 0, 0, W / 8};
Point(14) = {W, -D / 2, 0, W / 8};
Point(15) = {W, -D, 0, W / 8};
Point(16) = {W / 2, -D, 0, W / 8};
Point(17) = {0, -D, 0, W / 8};
Point(18) = {0, -D / 2, 0, W / 8};
Point(19) = {W / 2, -D / 2, 0, W / 8};
Line(11) = {12, 11};  // top, counter-clockwise around the block
Line(12) = {13, 12};
Line(13) = {14, 13};
Line(14) = {15, 14};
Line(15) = {16, 15};
Line(16) = {17, 16};
Line(17) = {18, 17};
Line(18) = {11, 18};
Line(19) = {12, 19};  // the cuts
Line(20) = {19, 16};
Line(21) = {18, 19};
Line(22) = {19, 14};
Curve Loop(11) = {18, 21, -19, 11};
Plane Surface(11) = {11};
Curve Loop(12) = {19, 22, 13, 12};
Plane Surface(12) = {12};
Curve Loop(13) = {17, 16, -20, -21};
Plane Surface(13) = {13};
Curve Loop(14) = {20, 15, 14, -22};
Plane Surface(14) = {14};
// ---- mesh size: hc within 10 mm of the contact point, as in the single-body files ----
Field[1] = Distance;
Field[1].PointsList = {1, 11};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hc;
Field[2].SizeMax = R / 8;
Field[2].DistMin = 10;
Field[2].DistMax = R;
Background Field = 2;
Physical Curve(1) = {1};
Physical Curve(2) = {4};
Physical Curve(3) = {5};
Physical Curve(4) = {2, 3};
Physical Surface(101) = {1};
Physical Surface(102) = {2};
Physical Curve(11) = {11, 12};
Physical Curve(12) = {13, 14};
Physical Curve(13) = {15, 16};
Physical Curve(14) = {17, 18};
Physical Surface(201) = {11};
Physical Surface(202) = {12};
Physical Surface(203) = {13};
Physical Surface(204) = {14};
