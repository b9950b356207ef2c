// The axisymmetric model's section of a stack of 1 to 5 layers on a substrate (inputs/multilayer_half.geo's
// block, revolved): r in [0, width], layer1 on top from z = 0 down, the substrate filling what the layers leave
// down to z = -depth, the indentation axis r = 0 (drawn as gmsh's x = r, y = z; indent places it in the plane
// y = 0 with z the axis). Triangles, or quadrilaterals with quads = 1, of size h_tip within r_fine of the tip's
// first contact (the origin), growing outside by grow times the distance up to h_far. Parameters (nm), named as
// the 3D meshes':
//   -setnumber n_layers 2 -setnumber t1 100 -setnumber t2 200 (t3, t4, t5 for more layers)
//   -setnumber width 1500 -setnumber depth 1500 -setnumber h_tip 10 -setnumber h_far 250 -setnumber r_fine 150
//   -setnumber grow 0.1 -setnumber quads 0
// Regions: layer1 ... layerN, substrate (when the layers leave room), boundaries top, bottom, axis, sides.
SetFactory("OpenCASCADE");
DefineConstant[ n_layers = 2, t1 = 100, t2 = 200, t3 = 100, t4 = 100, t5 = 100,
                width = 1500, depth = 1500, h_tip = 10, h_far = 250, r_fine = 150, grow = 0.1, quads = 0 ];
e = 1e-6 * width;
t[] = {t1, t2, t3, t4, t5};
If (n_layers < 1 || n_layers > 5 || n_layers != Round(n_layers))
  Error("axisymmetric_multilayer.geo: n_layers must be 1, 2, 3, 4 or 5, got %g", n_layers);
  Abort;
EndIf
zt[] = {0};   // zt[i]: bottom of layer i, zt[0] the top surface
For i In {1:n_layers}
  If (t[i - 1] <= 0)
    Error("axisymmetric_multilayer.geo: layer %g's thickness t%g must be > 0, got %g", i, i, t[i - 1]);
    Abort;
  EndIf
  zt[] += {zt[i - 1] - t[i - 1]};
  Rectangle(i) = {0, zt[i], 0, width, t[i - 1]};
EndFor
total = -zt[n_layers];
If (total > depth + 1e-3)
  Error("axisymmetric_multilayer.geo: the layers (%g nm) are thicker than the block (depth %g nm)", total, depth);
  Abort;
EndIf
has_substrate = depth - total > 1e-3;
ns = n_layers + has_substrate;
If (has_substrate)
  Rectangle(ns) = {0, -depth, 0, width, depth - total};
EndIf
If (ns > 1)
  BooleanFragments{ Surface{1}; Delete; }{ Surface{2:ns}; Delete; }
EndIf
Point(100) = {0, 0, 0};
Field[1] = Distance;
Field[1].PointsList = {100};
Field[2] = MathEval;
Field[2].F = Sprintf("Min(%g, %g + %g * Max(0, F1 - %g))", h_far, h_tip, grow, r_fine);
Background Field = 2;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.CharacteristicLengthFromPoints = 0;
If (quads)
  Mesh.RecombineAll = 1;
EndIf
For i In {1:n_layers}
  Physical Surface(Sprintf("layer%g", i)) = Surface In BoundingBox{-e, zt[i] - e, -e, width + e, zt[i - 1] + e, e};
EndFor
If (has_substrate)
  Physical Surface("substrate") = Surface In BoundingBox{-e, -depth - e, -e, width + e, zt[n_layers] + e, e};
EndIf
Physical Curve("top") = Curve In BoundingBox{-e, -e, -e, width + e, e, e};
Physical Curve("bottom") = Curve In BoundingBox{-e, -depth - e, -e, width + e, -depth + e, e};
Physical Curve("axis") = Curve In BoundingBox{-e, -depth - e, -e, e, e, e};
Physical Curve("sides") = Curve In BoundingBox{width - e, -depth - e, -e, width + e, e, e};
