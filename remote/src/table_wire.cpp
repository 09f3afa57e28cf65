#include "table_wire.hpp"

namespace stride::remote::table_wire {

dds::entity participant(const table_endpoint& where) {
  // the identity is the process's own (STRIDE_SECURITY): a path from another host means nothing
  dds_settings settings;
  settings.domain = where.domain;
  settings.config_file = where.config_file;
  return dds::make_participant(settings);
}

topics::topics(dds_entity_t participant) {
  dds_qos_t* qos = update_qos();
  update = dds::entity(dds::check(
      dds_create_topic(participant, &stride_table_update_desc, "stride_table_update", qos, nullptr),
      "topic stride_table_update"));
  dds_delete_qos(qos);
  qos = state_qos();
  state = dds::entity(dds::check(dds_create_topic(participant, &stride_table_table_state_desc,
                                                  "stride_table_state", qos, nullptr),
                                 "topic stride_table_state"));
  dds_delete_qos(qos);
}

dds_qos_t* update_qos() {
  return dds::reliable_qos();
}

dds_qos_t* state_qos() {
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(10));
  dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
  dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
  return qos;
}

}  // namespace stride::remote::table_wire
