<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.10" tiledversion="1.10.2" name="tiles" tilewidth="16" tileheight="16" tilecount="8" columns="4">
 <image source="tiles.png" width="64" height="32"/>
 <tile id="0">
  <properties>
   <property name="name" value="block"/>
  </properties>
  <objectgroup draworder="index" id="2">
   <object id="1" x="0" y="0" width="16" height="16"/>
  </objectgroup>
 </tile>
 <tile id="1">
  <properties>
   <property name="name" value="ramp"/>
  </properties>
  <objectgroup draworder="index" id="2">
   <object id="1" x="0" y="0">
    <polygon points="0,16 16,16 16,0"/>
   </object>
  </objectgroup>
 </tile>
 <tile id="2">
  <properties>
   <property name="name" value="ledge"/>
   <property name="one_way" type="bool" value="true"/>
  </properties>
  <objectgroup draworder="index" id="2">
   <object id="1" x="0" y="0" width="16" height="4"/>
  </objectgroup>
 </tile>
 <tile id="3">
  <properties>
   <property name="name" value="half"/>
  </properties>
  <objectgroup draworder="index" id="2">
   <object id="1" x="0" y="8" width="16" height="8"/>
  </objectgroup>
 </tile>
 <tile id="4" type="hazard">
  <properties>
   <property name="name" value="spikes"/>
   <property name="flag0" type="bool" value="true"/>
   <property name="hit_types" value="DEATH"/>
  </properties>
  <objectgroup draworder="index" id="2">
   <object id="1" x="0" y="0">
    <polygon points="0,16 4,8 8,12 12,8 16,16"/>
   </object>
  </objectgroup>
 </tile>
 <tile id="5">
  <properties>
   <property name="name" value="boulder"/>
  </properties>
  <objectgroup draworder="index" id="2">
   <object id="1" x="0" y="0" width="16" height="16">
    <ellipse/>
   </object>
  </objectgroup>
 </tile>
 <tile id="6" type="decoration">
  <properties>
   <property name="name" value="moss"/>
  </properties>
 </tile>
 <tile id="7">
  <properties>
   <property name="name" value="fence"/>
  </properties>
  <objectgroup draworder="index" id="2">
   <object id="1" x="8" y="0">
    <polyline points="0,0 0,16"/>
   </object>
  </objectgroup>
 </tile>
</tileset>
