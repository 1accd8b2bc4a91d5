plan examples/colorblocksworld/colorblocksworld.cp --domain Blocksworld --problem CaseStudy --search bfs --no-timing
