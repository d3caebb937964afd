// A misspelt block keyword.
spere { <0, 0, 0>, 1 }
