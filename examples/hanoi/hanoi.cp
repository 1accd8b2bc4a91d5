# The Tower of Hanoi as a planning domain, the source of the pattern "abstract to abstract"
# (../hanoi_to_blocks). A Place is a peg or a disc: what a disc can rest on. Smaller(d, p)
# says disc d may rest on place p (every disc may rest on every peg, and on every larger disc).
#
#   catplan validate examples/hanoi/hanoi.cp --problem ThreeDiscs --plan examples/hanoi/hanoi.plan

@present Hanoi(FreeSchema) begin
  Place::Ob
  On::Ob
  on_top::Hom(On, Place)
  on_below::Hom(On, Place)
  Smaller::Ob
  smaller_disc::Hom(Smaller, Place)
  smaller_place::Hom(Smaller, Place)
  Clear::AttrType(Bool)
  Peg::AttrType(Bool)
  isClear::Attr(Place, Clear)
  isPeg::Attr(Place, Peg)
end

# Three discs on the left peg, the small one on top.
@acset_colim ThreeOnLeft(Hanoi) begin
  (left, middle, right, small, medium, large)::Place
  isPeg(left) == true; isPeg(middle) == true; isPeg(right) == true
  isPeg(small) == false; isPeg(medium) == false; isPeg(large) == false
  (o1, o2, o3)::On
  on_top(o1) == large; on_below(o1) == left
  on_top(o2) == medium; on_below(o2) == large
  on_top(o3) == small; on_below(o3) == medium
  isClear(left) == false; isClear(middle) == true; isClear(right) == true
  isClear(small) == true; isClear(medium) == false; isClear(large) == false
  (s1, s2, s3, s4, s5, s6, s7, s8, s9, s10, s11, s12)::Smaller
  smaller_disc(s1) == small; smaller_place(s1) == medium
  smaller_disc(s2) == small; smaller_place(s2) == large
  smaller_disc(s3) == medium; smaller_place(s3) == large
  smaller_disc(s4) == small; smaller_place(s4) == left
  smaller_disc(s5) == small; smaller_place(s5) == middle
  smaller_disc(s6) == small; smaller_place(s6) == right
  smaller_disc(s7) == medium; smaller_place(s7) == left
  smaller_disc(s8) == medium; smaller_place(s8) == middle
  smaller_disc(s9) == medium; smaller_place(s9) == right
  smaller_disc(s10) == large; smaller_place(s10) == left
  smaller_disc(s11) == large; smaller_place(s11) == middle
  smaller_disc(s12) == large; smaller_place(s12) == right
end

# The three discs on a peg, in order.
@acset_colim ThreeOnAPeg(Hanoi) begin
  (peg, small, medium, large)::Place
  isPeg(peg) == true
  (o1, o2, o3)::On
  on_top(o1) == large; on_below(o1) == peg
  on_top(o2) == medium; on_below(o2) == large
  on_top(o3) == small; on_below(o3) == medium
end

@domain TowerOfHanoi(Hanoi) begin
  # move: a clear disc goes from where it rests onto a clear place it is smaller than.
  @rule move(disc, from, to) begin
    Pre => begin
      (disc, from, to)::Place
      o::On
      on_top(o) == disc
      on_below(o) == from
      s::Smaller
      smaller_disc(s) == disc
      smaller_place(s) == to
      isClear(disc) == true
      isClear(to) == true
    end
    Keep => begin
      (disc, from, to)::Place
      s::Smaller
      smaller_disc(s) == disc
      smaller_place(s) == to
    end
    Eff => begin
      moved::On
      on_top(moved) == disc
      on_below(moved) == to
      isClear(from) == true
      isClear(to) == false
    end
  end
end

# From the left peg to the right one.
@problem ThreeDiscs(TowerOfHanoi) begin
  initial = ThreeOnLeft
  goal = ThreeOnAPeg
end
