migrate tests/db/maps.cp --map Reverse --db sqlite:never-opened.db --sigma
absent: never-opened.db
