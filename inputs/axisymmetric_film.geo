// The axisymmetric model's section of a film on a substrate (inputs/berkovich_half.geo's block, revolved):
// r in [0, width], the film z in [-film, 0] over the substrate down to z = -depth, the indentation axis r = 0
// (drawn as gmsh's x = r, y = z; indent places it in the plane y = 0 with z the axis). Triangles, or
// quadrilaterals with quads = 1, of size h_tip within r_fine of the tip's first contact (the origin), growing
// outside by grow times the distance up to h_far. Parameters (nm), named as the 3D meshes' where they agree:
//   -setnumber film 300 -setnumber width 1500 -setnumber depth 1500 -setnumber h_tip 10 -setnumber h_far 250
//   -setnumber r_fine 150 -setnumber grow 0.1 -setnumber quads 0
SetFactory("OpenCASCADE");
DefineConstant[ film = 300, width = 1500, depth = 1500, h_tip = 10, h_far = 250, r_fine = 150, grow = 0.1,
                quads = 0 ];
If (film <= 0 || film >= depth)
  Error("axisymmetric_film.geo: the film (%g nm) must be thinner than the block (depth = %g nm)", film, depth);
  Abort;
EndIf
Rectangle(1) = {0, -film, 0, width, film};
Rectangle(2) = {0, -depth, 0, width, depth - film};
BooleanFragments{ Surface{1}; Delete; }{ Surface{2}; Delete; }
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
e = 1e-6 * width;
Physical Surface("film") = Surface In BoundingBox{-e, -film - e, -e, width + e, e, e};
Physical Surface("substrate") = Surface In BoundingBox{-e, -depth - e, -e, width + e, -film + e, e};
Physical Curve("top") = Curve In BoundingBox{-e, -e, -e, width + e, e, e};
Physical Curve("bottom") = Curve In BoundingBox{-e, -depth - e, -e, width + e, -depth + e, e};
Physical Curve("axis") = Curve In BoundingBox{-e, -depth - e, -e, e, e, e};
Physical Curve("sides") = Curve In BoundingBox{width - e, -depth - e, -e, width + e, e, e};
