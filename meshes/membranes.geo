// The seed's two membranes as one gmsh model: body 0 = (0,1)^2, body 1 = (1,2)x(0,1), each
// cut into N x N square subdomains with m x m cells (structured triangles, so the nodes of
// the two bodies on x = 1 coincide: node-to-node contact). Physical surfaces: 100 + k
// (body 0) and 200 + k (body 1), k = 1 + I + N J for the subdomain in column I, row J.
// Physical curves: 10 the edge x = 0 (fixed), 11 body 0's edge x = 1 (contact slave),
// 12 body 1's edge x = 1 (contact master). getdp/membranes.pro assembles on it.
DefineConstant[ N = 4, m = 8 ];
For b In {0:1}
  For J In {0:N}
    For I In {0:N}
      p~{b}~{I}~{J} = newp;
      Point(p~{b}~{I}~{J}) = {b + I / N, J / N, 0};
    EndFor
  EndFor
  For J In {0:N}  // horizontal lines
    For I In {0:N - 1}
      h~{b}~{I}~{J} = newl;
      Line(h~{b}~{I}~{J}) = {p~{b}~{I}~{J}, p~{b}~{I + 1}~{J}};
    EndFor
  EndFor
  For J In {0:N - 1}  // vertical lines
    For I In {0:N}
      v~{b}~{I}~{J} = newl;
      Line(v~{b}~{I}~{J}) = {p~{b}~{I}~{J}, p~{b}~{I}~{J + 1}};
    EndFor
  EndFor
  For J In {0:N - 1}
    For I In {0:N - 1}
      loop = newll;
      Curve Loop(loop) = {h~{b}~{I}~{J}, v~{b}~{I + 1}~{J}, -h~{b}~{I}~{J + 1}, -v~{b}~{I}~{J}};
      s = news;
      Plane Surface(s) = {loop};
      Transfinite Surface{s};
      Physical Surface(100 * (b + 1) + 1 + I + N * J) = {s};
    EndFor
  EndFor
EndFor
Transfinite Curve{:} = m + 1;
For J In {0:N - 1}
  edge0() += {v~{0}~{0}~{J}};
  slave() += {v~{0}~{N}~{J}};
  master() += {v~{1}~{0}~{J}};
EndFor
Physical Curve(10) = {edge0()};
Physical Curve(11) = {slave()};
Physical Curve(12) = {master()};
