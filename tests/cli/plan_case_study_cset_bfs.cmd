plan examples/colorblocksworld/colorblocksworld.cp --problem CaseStudy --search bfs --no-ground --no-timing
