// Behaviour costs from a file (`echoplan train --data DIR --costs FILE`): what each performance of
// a behaviour costs the robot, so that a problem, the planner and the baseline strategies weigh a
// slow push against a quick look (docs/feature-sets.md, "Behaviour costs").
#pragma once

#include <map>
#include <string>
#include <vector>

namespace echoplan::loop {

// Reads FILE, CSV with the header `behaviour,cost` and one row per priced behaviour (any order;
// unlisted behaviours keep the task's uniform `sense` reward). A cost is a finite number >= 0.
// Throws InputError naming the file and line of a wrong header, a ragged row, an empty or repeated
// behaviour, a behaviour not in `behaviours` (the data's), or a cost that is not a finite number
// >= 0.
std::map<std::string, double> load_behaviour_costs(const std::string& path,
                                                   const std::vector<std::string>& behaviours);

}  // namespace echoplan::loop
