// Using a name that was never declared.
#declare Radius = 1;
sphere { <0, 0, 0>, Radiuss }
