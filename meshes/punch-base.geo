// The elastic base under meshes/crowned-punch.geo: x, y in [-W, W], z in [-D, 0], its top
// touching the punch at the origin. Unstructured tetrahedra of size hc within Rz of the axis
// near the top, growing to `grow` hc at the far sides and bottom.
// Physical groups: surface 5 the top (the contact's master side), 6 the bottom (held),
// 7 the sides; volume 1.
SetFactory("OpenCASCADE");
DefineConstant[ W = 20, D = 20, Rz = 10, hc = 1, grow = 3 ];
Box(1) = {-W, -W, -D, 2 * W, 2 * W, D};
e = 1e-6;
Physical Surface(5) = Surface In BoundingBox{-W - e, -W - e, -e, W + e, W + e, e};
Physical Surface(6) = Surface In BoundingBox{-W - e, -W - e, -D - e, W + e, W + e, -D + e};
all[] = Surface{:};
sides[] = all[];
sides[] -= Surface In BoundingBox{-W - e, -W - e, -e, W + e, W + e, e};
sides[] -= Surface In BoundingBox{-W - e, -W - e, -D - e, W + e, W + e, -D + e};
Physical Surface(7) = {sides[]};
Physical Volume(1) = {1};
// The size: hc within Rz of the origin, growing linearly to grow hc at distance W.
Field[1] = MathEval;
Field[1].F = Sprintf("%g * (1 + (%g - 1) * Max(0, Sqrt(x^2 + y^2 + z^2) - %g) / (%g - %g))", hc, grow, Rz, W, Rz);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
// Delaunay: the same mesh in every process. HXT (Algorithm3D = 10, ten times faster: 3.6 s
// against 38.7 s at hc = 0.25) gave a mesh that changed with the process's environment even
// on one thread (another folder, OMP_NUM_THREADS or -nt 1 set: four different meshes at
// hc = 0.7, 9791 to 9800 nodes), so counts moved between runs by the mesh alone.
Mesh.Algorithm3D = 1;
