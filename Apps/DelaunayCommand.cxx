#include "Commands.h"
int runDelaunayCommand(int, char**) { return 1; }
