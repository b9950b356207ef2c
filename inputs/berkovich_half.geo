// Half model of a film on a substrate for a Berkovich indentation on the mirror plane y = 0 (y >= 0):
// the indenter's axis is the z axis, the top surface is z = 0. Tetrahedra, refined near the tip, or for a
// scratch test near the whole track, the segment from the origin to (track, 0, 0) (track = 0: a point).
// Parameters (nm): -setnumber film 300 -setnumber width 1500 -setnumber depth 1500
//                  -setnumber h_tip 10 -setnumber h_far 250 -setnumber r_fine 150 -setnumber track 0
// With -setnumber grow g > 0 the cells grow linearly past r_fine instead, h_tip + g (distance - r_fine) up to
// h_far (as in axisymmetric_film.geo): a fixed fraction of the distance to the tip.
SetFactory("OpenCASCADE");
DefineConstant[ film = 300, width = 1500, depth = 1500, h_tip = 10, h_far = 250, r_fine = 150, track = 0,
                grow = 0 ];
Box(1) = {-width, 0, -film, 2 * width, width, film};            // film
Box(2) = {-width, 0, -depth, 2 * width, width, depth - film};   // substrate
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
// The fine zone surrounds the scratch track: the distance field measures to points at most h_tip / 2
// apart along it, which overestimates the distance to the segment by at most h_tip / 4. The points
// steer the size field only; they are not part of the geometry, so no mesh node is forced onto them.
If (Fabs(track) >= width)
  Error("berkovich_half.geo: the track (%g nm) must end inside the block (|track| < width = %g nm)", track, width);
  Abort;
EndIf
n_track = Ceil(Fabs(track) / (0.5 * h_tip));
Point(100) = {0, 0, 0};
For i In {1:n_track}
  Point(100 + i) = {track * i / n_track, 0, 0};
EndFor
Field[1] = Distance;
Field[1].PointsList = {100:100 + n_track};
If (grow > 0)
  Field[2] = MathEval;
  Field[2].F = Sprintf("Min(%g, %g + %g * Max(0, F1 - %g))", h_far, h_tip, grow, r_fine);
Else
  Field[2] = Threshold;
  Field[2].InField = 1;
  Field[2].SizeMin = h_tip;
  Field[2].SizeMax = h_far;
  Field[2].DistMin = r_fine;
  Field[2].DistMax = 8 * r_fine;
EndIf
Background Field = 2;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.CharacteristicLengthFromPoints = 0;
e = 1e-3;
Physical Volume("film") = Volume In BoundingBox{-width - e, -e, -film - e, width + e, width + e, e};
Physical Volume("substrate") = Volume In BoundingBox{-width - e, -e, -depth - e, width + e, width + e, -film + e};
Physical Surface("top") = Surface In BoundingBox{-width - e, -e, -e, width + e, width + e, e};
Physical Surface("bottom") = Surface In BoundingBox{-width - e, -e, -depth - e, width + e, width + e, -depth + e};
Physical Surface("symmetry") = Surface In BoundingBox{-width - e, -e, -depth - e, width + e, e, e};
back() = Surface In BoundingBox{-width - e, width - e, -depth - e, width + e, width + e, e};
left() = Surface In BoundingBox{-width - e, -e, -depth - e, -width + e, width + e, e};
right() = Surface In BoundingBox{width - e, -e, -depth - e, width + e, width + e, e};
Physical Surface("sides") = {back(), left(), right()};
