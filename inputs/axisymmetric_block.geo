// The axisymmetric model's section of a block: r in [0, width], z in [-depth, 0], the indentation axis
// r = 0 (drawn as gmsh's x = r, y = z; indent places it in the plane y = 0 with z the axis). Triangles,
// or quadrilaterals with quads = 1, of size h_tip within r_fine of the tip's first contact (the origin),
// growing outside by grow times the distance (a size that jumps faster spoils the elements between) up to
// h_far. Parameters (nm):
//   -setnumber width 2000 -setnumber depth 2000 -setnumber h_tip 5 -setnumber h_far 200
//   -setnumber r_fine 200 -setnumber grow 0.1 -setnumber quads 0
SetFactory("OpenCASCADE");
DefineConstant[ width = 2000, depth = 2000, h_tip = 5, h_far = 200, r_fine = 200, grow = 0.1, quads = 0 ];
Rectangle(1) = {0, -depth, 0, width, depth};
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
Physical Surface("domain") = {1};
Physical Curve("top") = Curve In BoundingBox{-e, -e, -e, width + e, e, e};
Physical Curve("bottom") = Curve In BoundingBox{-e, -depth - e, -e, width + e, -depth + e, e};
Physical Curve("axis") = Curve In BoundingBox{-e, -depth - e, -e, e, e, e};
Physical Curve("sides") = Curve In BoundingBox{width - e, -depth - e, -e, width + e, e, e};
