// Endless recursion stops at the macro depth limit (200).
#macro Forever(N)
  Forever(N + 1)
#end
Forever(0)
