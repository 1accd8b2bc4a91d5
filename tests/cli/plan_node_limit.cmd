plan examples/colorblocksworld/colorblocksworld.cp --problem CaseStudy --search astar --heuristic hadd --max-nodes 5 --no-timing
