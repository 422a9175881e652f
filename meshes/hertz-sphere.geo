// A quarter of the lower half of a sphere of radius R centred at (0, 0, R): x >= 0, y >= 0,
// z <= R, touching the plane z = 0 at the origin. Mesh size hc within `zone` of the contact
// point, growing to R/4. Physical surfaces: 1 the plane x = 0, 2 the plane y = 0, 3 the cut
// z = R (the load), 4 the spherical surface (the contact); volume 1.
SetFactory("OpenCASCADE");
DefineConstant[ R = 10, hc = 0.2, zone = 2.5 ];
Sphere(1) = {0, 0, R, R};
Box(2) = {0, 0, 0, R, R, R};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
e = 1e-6;
sx[] = Surface In BoundingBox{-e, -e, -e, e, R + e, R + e};
sy[] = Surface In BoundingBox{-e, -e, -e, R + e, e, R + e};
st[] = Surface In BoundingBox{-e, -e, R - e, R + e, R + e, R + e};
sphere[] = Boundary{ Volume{3}; };
sphere[] -= {sx[], sy[], st[]};
Physical Surface(1) = {sx[]};
Physical Surface(2) = {sy[]};
Physical Surface(3) = {st[]};
Physical Surface(4) = {sphere[]};
Physical Volume(1) = {3};
// hc within `zone` of the contact point, then growing linearly to R/4.
Field[1] = MathEval;
Field[1].F = Sprintf("Min(%g, %g + 0.5 * Max(0, Sqrt(x * x + y * y + z * z) - %g))", R / 4, hc, zone);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
