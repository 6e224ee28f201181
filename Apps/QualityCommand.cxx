#include "Commands.h"
int runQualityCommand(int, char**) { return 1; }
