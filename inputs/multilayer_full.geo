// Full model of a stack of 1 to 5 layers on a substrate for an indentation along the z axis (the top
// surface is z = 0): the same block as multilayer_half.geo mirrored to y < 0, for runs without the
// symmetry plane (a rotated or off-axis indenter). layer1 is the top layer. Tetrahedra, refined near
// the tip (or the scratch track, from the origin to (track, 0, 0)) as in berkovich_full.geo.
// Parameters (nm), as in the half model:
//   -setnumber n_layers 2 -setnumber t1 100 -setnumber t2 200 (t3, t4, t5 for more layers)
//   -setnumber width 1500 -setnumber depth 1500 -setnumber h_tip 10 -setnumber h_far 250 -setnumber r_fine 150
//   -setnumber track 0
// depth is the total height: the substrate fills what the layers leave; when the layers fill it all
// there is no substrate (then two layers make exactly berkovich_full.geo's block and mesh).
SetFactory("OpenCASCADE");
DefineConstant[ n_layers = 2, t1 = 100, t2 = 200, t3 = 100, t4 = 100, t5 = 100,
                width = 1500, depth = 1500, h_tip = 10, h_far = 250, r_fine = 150,
                track = 0 ];
e = 1e-3;
t[] = {t1, t2, t3, t4, t5};
If (n_layers < 1 || n_layers > 5 || n_layers != Round(n_layers))
  Error("multilayer_full.geo: n_layers must be 1, 2, 3, 4 or 5, got %g", n_layers);
  Abort;
EndIf
zt[] = {0};   // zt[i]: bottom of layer i, zt[0] the top surface
For i In {1:n_layers}
  If (t[i - 1] <= 0)
    Error("multilayer_full.geo: layer %g's thickness t%g must be > 0, got %g", i, i, t[i - 1]);
    Abort;
  EndIf
  zt[] += {zt[i - 1] - t[i - 1]};
  Box(i) = {-width, -width, zt[i], 2 * width, 2 * width, t[i - 1]};
EndFor
total = -zt[n_layers];
If (total > depth + e)
  Error("multilayer_full.geo: the layers (%g nm) are thicker than the block (depth %g nm)", total, depth);
  Abort;
EndIf
has_substrate = depth - total > e;
nv = n_layers + has_substrate;
If (has_substrate)
  Box(nv) = {-width, -width, -depth, 2 * width, 2 * width, depth - total};
EndIf
If (nv > 1)
  BooleanFragments{ Volume{1}; Delete; }{ Volume{2:nv}; Delete; }
EndIf
// The fine zone surrounds the scratch track: the distance field measures to points at most h_tip / 2
// apart along it, which overestimates the distance to the segment by at most h_tip / 4. The points
// steer the size field only; they are not part of the geometry, so no mesh node is forced onto them.
If (Fabs(track) >= width)
  Error("multilayer_full.geo: the track (%g nm) must end inside the block (|track| < width = %g nm)", track, width);
  Abort;
EndIf
n_track = Ceil(Fabs(track) / (0.5 * h_tip));
Point(100) = {0, 0, 0};
For i In {1:n_track}
  Point(100 + i) = {track * i / n_track, 0, 0};
EndFor
Field[1] = Distance;
Field[1].PointsList = {100:100 + n_track};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_tip;
Field[2].SizeMax = h_far;
Field[2].DistMin = r_fine;
Field[2].DistMax = 8 * r_fine;
Background Field = 2;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.CharacteristicLengthFromPoints = 0;
// Literal names, one group each, so that indent can list every region's options from this text (-help).
Physical Volume("layer1") = Volume In BoundingBox{-width - e, -width - e, zt[1] - e, width + e, width + e, zt[0] + e};
If (n_layers >= 2)
  Physical Volume("layer2") = Volume In BoundingBox{-width - e, -width - e, zt[2] - e, width + e, width + e, zt[1] + e};
EndIf
If (n_layers >= 3)
  Physical Volume("layer3") = Volume In BoundingBox{-width - e, -width - e, zt[3] - e, width + e, width + e, zt[2] + e};
EndIf
If (n_layers >= 4)
  Physical Volume("layer4") = Volume In BoundingBox{-width - e, -width - e, zt[4] - e, width + e, width + e, zt[3] + e};
EndIf
If (n_layers >= 5)
  Physical Volume("layer5") = Volume In BoundingBox{-width - e, -width - e, zt[5] - e, width + e, width + e, zt[4] + e};
EndIf
If (has_substrate)
  Physical Volume("substrate") = Volume In BoundingBox{-width - e, -width - e, -depth - e,
                                                      width + e, width + e, -total + e};
EndIf
Physical Surface("top") = Surface In BoundingBox{-width - e, -width - e, -e, width + e, width + e, e};
Physical Surface("bottom") = Surface In BoundingBox{-width - e, -width - e, -depth - e,
                                                   width + e, width + e, -depth + e};
front() = Surface In BoundingBox{-width - e, -width - e, -depth - e, width + e, -width + e, e};
back() = Surface In BoundingBox{-width - e, width - e, -depth - e, width + e, width + e, e};
left() = Surface In BoundingBox{-width - e, -width - e, -depth - e, -width + e, width + e, e};
right() = Surface In BoundingBox{width - e, -width - e, -depth - e, width + e, width + e, e};
Physical Surface("sides") = {front(), back(), left(), right()};
