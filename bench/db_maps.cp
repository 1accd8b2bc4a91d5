# The maps of bench/db_bench.cpp: Δ along a delta map (the edges of a graph reversed) and the
# paper's colour split (a block's colour decides its Kitchenworld type).

@present Graph(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
end

@present ReversedGraph(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
end

@migration Reverse(ReversedGraph, Graph) begin
  V => V
  E => E
  src => tgt
  tgt => src
end

@present Blocks(FreeSchema) begin
  Block::Ob
  Color::AttrType(String)
  hasColor::Attr(Block, Color)
end

@present Kitchen(FreeSchema) begin
  (Object, BreadSliced, TomatoSliced, LettuceSliced, Plate, Knife)::Ob
  breadSlicedIsObject::Hom(BreadSliced, Object)
  tomatoSlicedIsObject::Hom(TomatoSliced, Object)
  lettuceSlicedIsObject::Hom(LettuceSliced, Object)
  plateIsObject::Hom(Plate, Object)
  knifeIsObject::Hom(Knife, Object)
end

@migration ColorSplit(Kitchen, Blocks) begin
  Object => Block
  BreadSliced => @join begin
    block::Block
    C::Color
    (hc:block → C)::hasColor
    (c:block → C)::(block -> "purple")
  end
  breadSlicedIsObject => block
  TomatoSliced => @join begin
    block::Block
    C::Color
    (hc:block → C)::hasColor
    (c:block → C)::(block -> "red")
  end
  tomatoSlicedIsObject => block
  LettuceSliced => @join begin
    block::Block
    C::Color
    (hc:block → C)::hasColor
    (c:block → C)::(block -> "green")
  end
  lettuceSlicedIsObject => block
  Plate => @join begin
    block::Block
    C::Color
    (hc:block → C)::hasColor
    (c:block → C)::(block -> "yellow")
  end
  plateIsObject => block
  Knife => @join begin
    block::Block
    C::Color
    (hc:block → C)::hasColor
    (c:block → C)::(block -> "blue")
  end
  knifeIsObject => block
end
