<?xml version="1.0" encoding="UTF-8"?>
<!-- The test kit: one tile per loader feature. Kept identical to kit.tsj. -->
<tileset version="1.10" tiledversion="1.10.2" name="kit" tilewidth="16" tileheight="16" tilecount="8" columns="0">
 <tile id="0">
  <!-- A ramp rising to the right: solid below the diagonal (16,0)-(0,16). -->
  <objectgroup draworder="index">
   <object id="1" x="0" y="0">
    <polygon points="0,16 16,16 16,0"/>
   </object>
  </objectgroup>
 </tile>
 <tile id="1">
  <!-- The bottom half of the tile. -->
  <objectgroup draworder="index">
   <object id="1" x="0" y="8" width="16" height="8"/>
  </objectgroup>
 </tile>
 <tile id="2">
  <!-- A one-way roof: a polyline with one_way on the object. -->
  <objectgroup draworder="index">
   <object id="1" name="roof" x="0" y="8">
    <properties>
     <property name="one_way" type="bool" value="true"/>
    </properties>
    <polyline points="0,0 8,-4 16,0"/>
   </object>
  </objectgroup>
 </tile>
 <tile id="3">
  <!-- A one-way wall facing left, its side set on the tile. -->
  <properties>
   <property name="one_way" type="bool" value="true"/>
   <property name="one_way_side" value="left"/>
  </properties>
  <objectgroup draworder="index">
   <object id="1" x="4" y="0">
    <polyline points="0,0 0,16"/>
   </object>
  </objectgroup>
 </tile>
 <tile id="4">
  <!-- An 8x4 rectangle turned 90 degrees clockwise about (8,0): covers (4,0)-(8,8). -->
  <objectgroup draworder="index">
   <object id="1" x="8" y="0" width="8" height="4" rotation="90"/>
  </objectgroup>
 </tile>
 <tile id="5">
  <objectgroup draworder="index">
   <object id="1" x="0" y="4" width="16" height="8">
    <capsule/>
   </object>
  </objectgroup>
 </tile>
 <tile id="6" type="crate">
  <!-- User bits: flag2 and flag5 on the tile; the right object turns flag5 off. -->
  <properties>
   <property name="flag2" type="bool" value="true"/>
   <property name="flag5" type="bool" value="true"/>
  </properties>
  <objectgroup draworder="index">
   <object id="1" name="left" x="0" y="0" width="8" height="16"/>
   <object id="2" name="right" x="8" y="0" width="8" height="16">
    <properties>
     <property name="flag5" type="bool" value="false"/>
    </properties>
   </object>
  </objectgroup>
 </tile>
 <tile id="7" type="coin">
  <!-- No collision objects: blocks nothing, but its properties come along. -->
  <properties>
   <property name="hit_types" value="COLLECT"/>
   <property name="value" type="int" value="5"/>
  </properties>
 </tile>
</tileset>
