# Small graphs for the CLI tests of `catplan homs`.
@present Graph(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
end

# A directed 3-cycle a -> b -> c -> a.
@acset_colim Cycle3(Graph) begin
  (a, b, c)::V
  (ab, bc, ca)::E
  src(ab) == a; tgt(ab) == b
  src(bc) == b; tgt(bc) == c
  src(ca) == c; tgt(ca) == a
end

# Two directed 3-cycles sharing the vertex v1, plus a loop on v1.
@acset_colim Bowtie(Graph) begin
  (v1, v2, v3, v4, v5)::V
  (e1, e2, e3, e4, e5, e6, loop)::E
  src(e1) == v1; tgt(e1) == v2
  src(e2) == v2; tgt(e2) == v3
  src(e3) == v3; tgt(e3) == v1
  src(e4) == v1; tgt(e4) == v4
  src(e5) == v4; tgt(e5) == v5
  src(e6) == v5; tgt(e6) == v1
  src(loop) == v1; tgt(loop) == v1
end

@acset Path2(Graph) begin
  V = 3; E = 2; src = [1, 2]; tgt = [2, 3]
end
