// A crowned cylindrical punch: radius Rp, height H, its bottom the cap of a sphere of radius
// Rc centred on the axis at z = Rc (touching the plane z = 0 at the origin), its top flat at
// z = H. Unstructured tetrahedra of size hc everywhere (edp/real-mesh-3d.edp meshes it and
// meshes/punch-base.geo separately: the contact meshes do not match).
// Physical groups: surface 1 the crowned bottom (the contact's slave side), 2 the side,
// 3 the top (loaded, held sideways); volume 1.
SetFactory("OpenCASCADE");
DefineConstant[ Rp = 8, H = 10, Rc = 60, hc = 1 ];
Cylinder(1) = {0, 0, 0, 0, 0, H, Rp};
Sphere(2) = {0, 0, Rc, Rc};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
e = 1e-6;
top[] = Surface In BoundingBox{-Rp - e, -Rp - e, H - e, Rp + e, Rp + e, H + e};
capHeight = Rc - Sqrt(Rc^2 - Rp^2);
bottom[] = Surface In BoundingBox{-Rp - e, -Rp - e, -e, Rp + e, Rp + e, capHeight + e};
all[] = Surface{:};
side[] = all[];
side[] -= top[];
side[] -= bottom[];
Physical Surface(1) = {bottom[]};
Physical Surface(2) = {side[]};
Physical Surface(3) = {top[]};
Physical Volume(1) = {3};
Mesh.MeshSizeMin = hc;
Mesh.MeshSizeMax = hc;
Mesh.Algorithm3D = 1;    // Delaunay: the same mesh on every run (HXT gave a different one each time here, even on one thread)
