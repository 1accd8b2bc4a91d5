migrate tests/db/maps.cp --map TwoPaths --db postgresql://nowhere.invalid/db --print-sql --from G --to PathsOfTwo
