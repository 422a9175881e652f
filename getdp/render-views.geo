// Renders one view of ffeti-solve's views file (displacement 0, contact pressure 1, active
// set 2, von Mises 3) over the mesh into a PNG, with gmsh's own renderer (off screen
// under xvfb-run). Used by scripts/getdp-hertz.sh for docs/getdp.md:
//   xvfb-run -a gmsh -setstring mesh hertz.msh -setstring views hertz-ffeti.msh -setnumber view 3
//        -setnumber vmax 3000 -setnumber scale 1 -setnumber tx 0 -setnumber ty 0 -setstring out a.png render-views.geo
// scale zooms; (tx, ty) shifts the model (model units) before zooming. Relative paths are
// taken from the folder gmsh runs in (gmsh itself would take them from this file's folder:
// run from elsewhere, it drew a blank picture and wrote it beside this file).
DefineConstant[ mesh = "hertz.msh", views = "hertz-ffeti.msh", view = 3, vmax = 3000,
                scale = 1, tx = 0, ty = 0, out = "view.png" ];
General.AbortOnError = 4;  // an Error() below ends gmsh with a non-zero exit status
here = StrCat(GetEnv("PWD"), "/");
// A path is absolute when "#" + path begins with "#/".
meshFile = StrChoice(StrCmp(StrReplace(StrCat("#", mesh), "#/", ""), StrCat("#", mesh)), mesh, StrCat(here, mesh));
viewsFile = StrChoice(StrCmp(StrReplace(StrCat("#", views), "#/", ""), StrCat("#", views)), views, StrCat(here, views));
outFile = StrChoice(StrCmp(StrReplace(StrCat("#", out), "#/", ""), StrCat("#", out)), out, StrCat(here, out));
If (!FileExists(StrCat(meshFile)))
  Error(StrCat("render-views.geo: the mesh file ", meshFile, " does not exist (-setstring mesh)"));
EndIf
If (!FileExists(StrCat(viewsFile)))
  Error(StrCat("render-views.geo: the views file ", viewsFile, " does not exist (-setstring views)"));
EndIf
Merge Str(meshFile);
Merge Str(viewsFile);
If (view < 0 || view >= PostProcessing.NbViews)
  Error(Sprintf("render-views.geo: view %g does not exist (the views file holds %g)", view, PostProcessing.NbViews));
EndIf
Mesh.SurfaceEdges = 0;
Mesh.Lines = 0;
Mesh.Points = 0;
General.SmallAxes = 0;
General.Trackball = 0;
General.RotationX = 0;
General.RotationY = 0;
General.RotationZ = 0;
For v In {0:PostProcessing.NbViews - 1}
  View[v].Visible = (v == view);
  View[v].Light = 0;
EndFor
View[view].RangeType = 2;  // custom range, the same on every picture
View[view].CustomMin = 0;
View[view].CustomMax = vmax;
General.ScaleX = scale;
General.ScaleY = scale;
General.TranslationX = tx;
General.TranslationY = ty;
Draw;
Print Str(outFile);
Exit;
