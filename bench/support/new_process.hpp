#pragma once

#include <string>

namespace nome::bench {

// What this executable prints when run again with `arguments`, started after a pause of 10 s: these VMs
// hand freed memory back to the host after some seconds (virtio-balloon free page reporting; 3 s were not
// always enough after the last run), after which touching it costs host faults, as memory never touched
// does. A command started by a user finds its memory so, not as the work before it left it. Empty if the
// run failed.
std::string output_of_new_process(const std::string& arguments);

}  // namespace nome::bench
