// An open-end spanner gripping a hexagonal nut (2D, mm), after the seed's Figure 3.
// The nut (across flats 10, bolt hole radius 2.5) sits in the spanner's slot with a
// clearance c on the jaw faces and the slot's back; the handle runs to x = -L.
// lc: mesh size away from the nut; the nut and the jaw faces get lc/3 (1.9: 2650 unknowns,
// about the seed's 2606; 0.4: about 50,000).
// Physical curves: 1 upper outer curve of the head (design), 2 lower outer curve (design),
// 3 jaw faces, rounded corners and slot back (contact masters), 4 handle end (load), 5 other spanner
// boundary, 6 nut outline (contact slaves), 7 bolt hole (fixed). Surfaces: 1 spanner, 2 nut.
DefineConstant[ lc = 1.9, c = 0.01, L = 90 ];
R = 10 / Sqrt(3);          // circumradius of the hexagon
f = 5;                     // half across flats
xt = 6.5;                  // jaw tips
tj = 3;                    // jaw tip thickness
lf = lc / 3;
rf = 1;                    // radius of the slot's back corners

// Spanner outline, counter-clockwise (so that FreeFEM gets positive triangles).
Point(1) = {-L, -5, 0, lc};
Point(2) = {-18, -5, 0, lc};
Point(3) = {xt, -f - c - tj, 0, lf};
Point(4) = {xt, -f - c, 0, lf};
// the slot's back corners are rounded (radius rf), as on real spanners: a sharp re-entrant
// corner would be a stress singularity that grows without bound under refinement
Point(5) = {-R - c + rf, -f - c, 0, lf};
Point(51) = {-R - c + rf, -f - c + rf, 0, lf};
Point(52) = {-R - c, -f - c + rf, 0, lf};
Point(6) = {-R - c, f + c - rf, 0, lf};
Point(61) = {-R - c + rf, f + c - rf, 0, lf};
Point(62) = {-R - c + rf, f + c, 0, lf};
Point(7) = {xt, f + c, 0, lf};
Point(8) = {xt, f + c + tj, 0, lf};
Point(9) = {-18, 5, 0, lc};
Point(10) = {-L, 5, 0, lc};
// control points of the outer curves of the head (B-splines: they pass through their first
// and last points only, tangent to the control polygon there). The first control points
// 19 and 20 lie on the handle's edges, so the head leaves the handle tangentially: a kink
// there would be a re-entrant corner, a stress singularity whose peak grows without bound
// under refinement and that no smooth design motion can remove (it did: 94, 99, 125 MPa at
// lc = 1.9, 1.0, 0.4).
Point(19) = {-16, -5, 0, lc};
Point(20) = {-16, 5, 0, lc};
Point(11) = {-15, -8, 0, lc};
Point(12) = {-10, -13, 0, lc};
Point(13) = {-3, -14.5, 0, lc};
Point(14) = {3, -12, 0, lc};
Point(15) = {3, 12, 0, lc};
Point(16) = {-3, 14.5, 0, lc};
Point(17) = {-10, 13, 0, lc};
Point(18) = {-15, 8, 0, lc};

Line(1) = {1, 2};
BSpline(2) = {2, 19, 11, 12, 13, 14, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Circle(11) = {5, 51, 52};
Line(5) = {52, 6};
Circle(12) = {6, 61, 62};
Line(6) = {62, 7};
Line(7) = {7, 8};
BSpline(8) = {8, 15, 16, 17, 18, 20, 9};
Line(9) = {9, 10};
Line(10) = {10, 1};
Curve Loop(1) = {1, 2, 3, 4, 11, 5, 12, 6, 7, 8, 9, 10};
Plane Surface(1) = {1};

// Nut: hexagon with flats at y = +-f, bolt hole at the centre.
Point(21) = {R, 0, 0, lf};
Point(22) = {R / 2, f, 0, lf};
Point(23) = {-R / 2, f, 0, lf};
Point(24) = {-R, 0, 0, lf};
Point(25) = {-R / 2, -f, 0, lf};
Point(26) = {R / 2, -f, 0, lf};
Point(27) = {0, 0, 0, lf};
Point(28) = {2.5, 0, 0, lf};
Point(29) = {-2.5, 0, 0, lf};
Line(21) = {21, 22};
Line(22) = {22, 23};
Line(23) = {23, 24};
Line(24) = {24, 25};
Line(25) = {25, 26};
Line(26) = {26, 21};
Circle(27) = {28, 27, 29};
Circle(28) = {29, 27, 28};
Curve Loop(2) = {21, 22, 23, 24, 25, 26};
Curve Loop(3) = {27, 28};
Plane Surface(2) = {2, 3};

Physical Curve(1) = {8};
Physical Curve(2) = {2};
Physical Curve(3) = {4, 11, 5, 12, 6};
Physical Curve(4) = {10};
Physical Curve(5) = {1, 3, 7, 9};
Physical Curve(6) = {21, 22, 23, 24, 25, 26};
Physical Curve(7) = {27, 28};
Physical Surface(1) = {1};
Physical Surface(2) = {2};
