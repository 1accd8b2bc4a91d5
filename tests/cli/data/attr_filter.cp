# The reference stack's attribute-filter migration (reference §5.5 (b)): Y is the X whose label
# is "foo", with constant attributes written in Julia's pipe form.

@present SchAttrSet(FreeSchema) begin
  X::Ob
  Label::AttrType(String)
  hasLabel::Attr(X, Label)
  MyBool::AttrType(Bool)
  MyString::AttrType(String)
end

@present SchAttrSet2(FreeSchema) begin
  X::Ob
  Y::Ob
  m::Hom(Y, X)
  A::AttrType(Bool)
  f::Attr(Y, A)
  B::AttrType(String)
  g::Attr(Y, B)
end

M = @migration SchAttrSet2 SchAttrSet begin
  X => X
  Y => @join begin
    x::X
    L::Label
    (hl:x→L) :: hasLabel
    (foo:x→L) :: (x->"foo")
  end
  m => x
  A => MyBool
  f => (x |> (a -> false))
  B => MyString
  g => (x |> (a -> "unknown"))
end

@acset T(SchAttrSet) begin
  X = 2
  hasLabel = ["foo", "bar"]
end
