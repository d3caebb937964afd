// Strings compare with = != < > like strcmp (POV-Ray 3.7's mesh camera macros rely on it).
#declare Name = "beta";
#if (Name != "")
  sphere { <(Name = "beta"), (Name < "gamma"), (Name > "alpha")>, 0.5 }
#end
