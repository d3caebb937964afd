light_source { <0, 5, 0>, 1 spotlight phong 1 }
