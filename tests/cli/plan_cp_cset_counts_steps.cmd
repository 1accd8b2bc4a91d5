plan tests/cli/data/roads.cp --problem ToD --no-ground --search bfs --no-timing
