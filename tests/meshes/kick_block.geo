// A quarter block [0, L] x [0, L] x [-L, 0] of hexahedra with a uniformly fine core [0, Lc]^2 x [-Lc, 0]
// of Nc cells per edge around the indentation point (the origin), graded outside it by a geometric
// progression of No cells whose first is as large as a core cell. For Kick's law: a sharp tip has no
// length scale, so P / h^2 stays constant only while every ring of nodes entering the contact is as
// wide as the last, which a mesh graded right from the tip does not give.
// -setnumber L <nm> -setnumber Lc <nm> -setnumber Nc <cells> -setnumber No <cells>
DefineConstant[ L = 2000, Lc = 100, Nc = 10, No = 7 ];
e = Lc / Nc;
// the ratio r of the outer progression: e (r^No - 1) / (r - 1) = L - Lc, by fixed-point iteration
// (a contraction near the root for any block much larger than its core)
r = 2;
For k In {1:100}
  r = (1 + (L - Lc) * (r - 1) / e)^(1 / No);
EndFor
ones[] = {};
cum[] = {};  // layer tops of the outer progression, as fractions of L - Lc
For k In {1:No}
  ones[] += {1};
  cum[] += {e * (r^k - 1) / (r - 1) / (L - Lc)};
EndFor
Point(1) = {0, 0, 0}; Point(2) = {Lc, 0, 0}; Point(3) = {L, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3};
Transfinite Curve{1} = Nc + 1;
Transfinite Curve{2} = No + 1 Using Progression r;
// along y, then down in z: each extrusion returns, per source entity, its top, then the new entity
a[] = Extrude {0, Lc, 0} { Curve{1, 2}; Layers{Nc}; Recombine; };
b[] = Extrude {0, L - Lc, 0} { Curve{a[0], a[4]}; Layers{ones[], cum[]}; Recombine; };
c[] = Extrude {0, 0, -Lc} { Surface{a[1], a[5], b[1], b[5]}; Layers{Nc}; Recombine; };
d[] = Extrude {0, 0, -(L - Lc)} { Surface{c[0], c[6], c[12], c[18]}; Layers{ones[], cum[]}; Recombine; };
tol = 1e-6 * L;
Physical Volume("domain") = {c[1], c[7], c[13], c[19], d[1], d[7], d[13], d[19]};
Physical Surface("top") = Surface In BoundingBox{-tol, -tol, -tol, L + tol, L + tol, tol};
Physical Surface("bottom") = Surface In BoundingBox{-tol, -tol, -L - tol, L + tol, L + tol, -L + tol};
Physical Surface("front") = Surface In BoundingBox{-tol, -tol, -L - tol, L + tol, tol, tol};
Physical Surface("back") = Surface In BoundingBox{-tol, L - tol, -L - tol, L + tol, L + tol, tol};
Physical Surface("left") = Surface In BoundingBox{-tol, -tol, -L - tol, tol, L + tol, tol};
Physical Surface("right") = Surface In BoundingBox{L - tol, -tol, -L - tol, L + tol, L + tol, tol};
