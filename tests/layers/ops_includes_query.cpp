// An ops source including a query header: query is beside ops, not below it, so this must not compile.
#include "nome/query/ray.hpp"
